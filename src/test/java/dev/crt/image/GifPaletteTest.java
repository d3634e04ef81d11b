package dev.crt.image;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Random;
import org.junit.jupiter.api.Test;

class GifPaletteTest {
    @Test
    void fewColoursAreKeptExactly() {
        MedianCutQuantizer q = new MedianCutQuantizer();
        q.add(new int[] {0x102030, 0x102030, 0xff0000, 0x00ff00, 0x0000ff});
        Palette p = q.palette(255);
        assertThat(p.size()).isEqualTo(4);
        for (int c : new int[] {0x102030, 0xff0000, 0x00ff00, 0x0000ff}) {
            assertThat(p.colour(p.nearest(c >> 16 & 0xff, c >> 8 & 0xff, c & 0xff))).isEqualTo(c);
        }
    }

    @Test
    void gradientGetsManyEntries() {
        int[] ramp = new int[256];
        for (int i = 0; i < 256; i++) ramp[i] = (i << 16) | (i << 8) | i;
        MedianCutQuantizer q = new MedianCutQuantizer();
        q.add(ramp);
        // 64 histogram bins per channel: a grey ramp keeps one entry per bin, four levels apart.
        assertThat(q.palette(255).size()).isEqualTo(64);
    }

    @Test
    void paletteDoesNotDependOnPixelOrder() {
        int[] pixels = new Random(7).ints(5000, 0, 1 << 24).toArray();
        int[] reversed = new int[pixels.length];
        for (int i = 0; i < pixels.length; i++) reversed[i] = pixels[pixels.length - 1 - i];
        MedianCutQuantizer a = new MedianCutQuantizer();
        MedianCutQuantizer b = new MedianCutQuantizer();
        a.add(pixels);
        b.add(reversed);
        Palette pa = a.palette(255);
        Palette pb = b.palette(255);
        assertThat(pa.size()).isEqualTo(255);
        for (int i = 0; i < pa.size(); i++) assertThat(pa.colour(i)).isEqualTo(pb.colour(i));
    }

    @Test
    void nearestMatchesAFullSearch() {
        Random random = new Random(11);
        int[] colours = random.ints(200, 0, 1 << 24).toArray();
        Palette p = new Palette(colours);
        for (int n = 0; n < 20000; n++) {
            int r = random.nextInt(256), g = random.nextInt(256), b = random.nextInt(256);
            int best = 0;
            long bestDistance = Long.MAX_VALUE;
            for (int i = 0; i < colours.length; i++) {
                long d = sq((colours[i] >> 16 & 0xff) - r) + sq((colours[i] >> 8 & 0xff) - g) + sq((colours[i] & 0xff) - b);
                if (d < bestDistance) { bestDistance = d; best = i; }
            }
            assertThat(p.nearest(r, g, b)).isEqualTo(best);
        }
    }

    private static long sq(int v) { return (long) v * v; }
}
