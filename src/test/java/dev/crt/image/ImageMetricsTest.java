package dev.crt.image;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import org.junit.jupiter.api.Test;

/**
 * SSIM against the reference implementation of scikit-image 0.26.0, computed with
 * {@code structural_similarity(a, b, channel_axis=2, gaussian_weights=True, sigma=1.5,
 * use_sample_covariance=False, data_range=255)}, the settings of Wang et al. (2004), on the
 * images built below (the same formulas in numpy, as float64 arrays of shape (40, 48, 3)).
 */
class ImageMetricsTest {
    private static final int W = 48, H = 40;

    private static double[] image(int kind) {
        double[] v = new double[3 * W * H];
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                for (int c = 0; c < 3; c++) {
                    double a = 128 + 100 * Math.sin(x / 5.0 + c) * Math.cos(y / 7.0);
                    double value = switch (kind) {
                        case 0 -> a;
                        case 1 -> Math.min(255, Math.max(0, a + 25 * Math.sin(0.37 * x * y + 1.3 * c)));
                        default -> 0.8 * a + 20;
                    };
                    v[3 * (y * W + x) + c] = value;
                }
            }
        }
        return v;
    }

    @Test
    void ssimMatchesTheReferenceImplementation() {
        double[] a = image(0);
        assertThat(ImageMetrics.ssim(a, image(1), W, H)).isCloseTo(0.6530468521311475, within(1e-9));
        assertThat(ImageMetrics.ssim(a, image(2), W, H)).isCloseTo(0.9753219792092277, within(1e-9));
    }

    @Test
    void ssimIsOneForEqualPicturesAndSymmetric() {
        double[] a = image(0), b = image(1);
        assertThat(ImageMetrics.ssim(a, a, W, H)).isCloseTo(1, within(1e-12));
        assertThat(ImageMetrics.ssim(a, b, W, H)).isCloseTo(ImageMetrics.ssim(b, a, W, H), within(1e-12));
    }

    @Test
    void rmseIsInLevels() {
        double[] a = {0, 0, 0, 10, 10, 10}, b = {3, 3, 3, 6, 6, 6};
        assertThat(ImageMetrics.rmse(a, b)).isCloseTo(Math.sqrt((9 + 16) / 2.0), within(1e-12));
    }

    @Test
    void levelsAreTheBytesTheWritersWrite() {
        FrameBuffer fb = new FrameBuffer(2, 1);
        fb.set(0, 0, 0.5, 0.25, 2);
        fb.set(1, 0, -1, 0.001, 0.9);
        double[] l = ImageMetrics.levels(fb, 2.2);
        for (int k = 0; k < 6; k++) assertThat(l[k]).isEqualTo(ImageFiles.toByte(fb.data()[k], 2.2));
    }

    @Test
    void picturesSmallerThanTheWindowAreRefused() {
        assertThatThrownBy(() -> ImageMetrics.ssim(new double[30], new double[30], 10, 1))
                .isInstanceOf(IllegalArgumentException.class).hasMessageContaining("11×11");
    }
}
