package dev.crt.studio;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

/** The coarse pass the first picture waits for stays small whatever the picture's size. */
class RenderJobTest {
    @Test
    void theCoarsePassHasAboutTwoThousandPixelsAndIsNeverFinerThanEveryEighth() {
        for (int[] size : new int[][] {{800, 600}, {800, 450}, {1280, 720}, {1920, 1080}, {3840, 2160}}) {
            int step = RenderJob.coarseStep(size[0], size[1]);
            long pixels = (long) ((size[0] + step - 1) / step) * ((size[1] + step - 1) / step);
            assertThat(pixels).as("coarse pixels of %dx%d", size[0], size[1]).isBetween(1000L, (long) RenderJob.COARSE_PIXELS * 11 / 10);
        }
        assertThat(RenderJob.coarseStep(320, 240)).isEqualTo(RenderJob.COARSE);
        assertThat(RenderJob.coarseStep(1, 1)).isEqualTo(RenderJob.COARSE);
    }
}
