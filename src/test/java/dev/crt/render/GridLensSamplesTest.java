package dev.crt.render;

import static dev.crt.render.Scenes.rgb;
import static dev.crt.render.Scenes.v;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import dev.crt.image.FrameBuffer;
import dev.crt.scene.ApertureShape;
import dev.crt.scene.Camera;
import dev.crt.scene.GradientBackground;
import dev.crt.scene.Sampler;
import dev.crt.scene.Scene;
import dev.crt.scene.Settings;
import dev.crt.scene.SourceSpan;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * The grid sampler with a lens, which makes a sub-pixel's part of its lens rays once for all of
 * them: every pixel is the mean of the rays made one by one from their sub-pixel centres and lens
 * points ({@link CameraRays#aim} and {@link CameraRays#throughLens}).
 */
class GridLensSamplesTest {
    @Test
    void eachPixelIsTheMeanOfItsLensRaysMadeOneByOne() {
        int w = 12, h = 9, n = 3, m = 5;
        for (ApertureShape shape : new ApertureShape[] {ApertureShape.CIRCLE, ApertureShape.HEXAGON}) {
            Camera cam = new Camera(v(0.3, 1, -6), v(0, 0.5, 0), 50, 10, 300, 4, shape, SourceSpan.NONE);
            Settings s = new Settings("lens", "", "", "", List.of(), cam,
                    new GradientBackground(rgb(0.9, 0.6, 0.2), rgb(0.1, 0.3, 0.8)), n, m, 2, 1, w, h, Sampler.GRID, 5, 0);
            FrameBuffer image = Renderer.prepare(new Scene("lens", s, List.of())).render(1, RenderMonitor.NONE);
            CameraRays camera = new CameraRays(cam, w, h);
            BackgroundShader sky = new BackgroundShader(s.effectiveBackground(), s.outputGamma());
            PixelRandom random = new PixelRandom();
            double[] lens = new double[2], o = new double[3], d = new double[3], c = new double[3];
            for (int j = 0; j < h; j++) {
                for (int i = 0; i < w; i++) {
                    random.seed(i, j, 5);
                    double[] sum = new double[3];
                    for (int b = 0; b < n; b++) {
                        for (int a = 0; a < n; a++) {
                            for (int k = 0; k < m; k++) {
                                double u1 = random.next(), u2 = random.next(), u3 = random.next();
                                camera.aperture.sample(u1, u2, u3, lens);
                                double[] aim = new double[CameraRays.AIM];
                                camera.aim(i, j, (a + 0.5) / n, (b + 0.5) / n, aim);
                                camera.throughLens(aim, lens[0], lens[1], o, d);
                                sky.shade(d[0], d[1], d[2], c);
                                for (int q = 0; q < 3; q++) sum[q] += c[q] / (n * n * m);
                            }
                        }
                    }
                    for (int q = 0; q < 3; q++) assertThat((double) image.get(i, j, q)).as("%d %d", i, j).isCloseTo(sum[q], within(1e-6));
                }
            }
        }
    }
}
