package dev.crt.geom;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

/** The Sobol points against the published start of the sequence, and the stratification scrambling must keep. */
class SobolTest {
    private static double unscrambled(int index, int dim) {
        return (Sobol.bits(index, dim) & 0xffffffffL) * 0x1p-32;
    }

    @Test
    void theFirstPointsAreTheSequencesPublishedOnes() {
        // In index order (point k is the XOR of the direction numbers of k's set bits; the lists
        // often printed are in Gray-code order, the same points visited differently).
        // Dimension 0 is van der Corput's: direction numbers 1/2, 1/4, 1/8.
        double[] d0 = {0, 0.5, 0.25, 0.75, 0.125, 0.625, 0.375, 0.875};
        // Dimension 1, polynomial x + 1, m = 1: direction numbers 1/2, 3/4, 5/8.
        double[] d1 = {0, 0.5, 0.75, 0.25, 0.625, 0.125, 0.375, 0.875};
        // Dimension 2, polynomial x² + x + 1, m = 1, 3 (Joe and Kuo): direction numbers 1/2, 3/4, 3/8.
        double[] d2 = {0, 0.5, 0.75, 0.25, 0.375, 0.875, 0.625, 0.125};
        for (int k = 0; k < 8; k++) {
            assertThat(unscrambled(k, 0)).as("dim 0, point %d", k).isEqualTo(d0[k]);
            assertThat(unscrambled(k, 1)).as("dim 1, point %d", k).isEqualTo(d1[k]);
            assertThat(unscrambled(k, 2)).as("dim 2, point %d", k).isEqualTo(d2[k]);
        }
    }

    @Test
    void scrambledFirstTwoDimensionsStayAZeroTwoNet() {
        for (int seed : new int[] {0, 1, 0x5eed, -123456789}) {
            for (int m = 1; m <= 8; m++) {
                int n = 1 << m;
                for (int xBits = 0; xBits <= m; xBits++) {
                    int yBits = m - xBits;
                    int[] count = new int[n];
                    for (int k = 0; k < n; k++) {
                        int cx = (int) (Sobol.sample(k, 0, seed) * (1 << xBits));
                        int cy = (int) (Sobol.sample(k, 1, seed ^ 0x9e37) * (1 << yBits));
                        count[(cy << xBits) | cx]++;
                    }
                    for (int c : count) assertThat(c).as("seed %d, %d points, cell %dx%d", seed, n, 1 << xBits, 1 << yBits).isEqualTo(1);
                }
            }
        }
    }

    @Test
    void everyDimensionIsStratifiedAndScramblingChangesThePoints() {
        for (int dim = 0; dim < Sobol.DIMENSIONS; dim++) {
            for (int m = 0; m <= 10; m++) {
                int n = 1 << m;
                boolean[] seen = new boolean[n];
                for (int k = 0; k < n; k++) {
                    int cell = (int) (Sobol.sample(k, dim, 77 + dim) * n);
                    assertThat(seen[cell]).as("dim %d, %d points", dim, n).isFalse();
                    seen[cell] = true;
                }
            }
            assertThat(Sobol.sample(3, dim, 1)).isNotEqualTo(Sobol.sample(3, dim, 2));
            assertThat(Sobol.sample(0, dim, 1)).isBetween(0.0, 1.0);
        }
    }
}
