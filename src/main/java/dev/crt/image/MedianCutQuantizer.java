package dev.crt.image;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.List;

/**
 * Chooses a palette for a set of images by median cut: colours are counted in a histogram with six
 * bits per channel (fine enough for smooth gradients to get many entries), then the box of colours
 * with the largest squared error is split at its median along its widest channel until the palette
 * is full. Each entry is the mean of the pixels its box holds, so it is a colour the images use.
 * The result depends only on the pixels added, not on the order they came in.
 */
public final class MedianCutQuantizer {
    private static final int BITS = 6;
    private static final int BINS = 1 << (3 * BITS);

    private final long[] count = new long[BINS];
    private final long[] sumRed = new long[BINS];
    private final long[] sumGreen = new long[BINS];
    private final long[] sumBlue = new long[BINS];

    /** Counts the pixels of an image, packed 0xRRGGBB. */
    public void add(int[] rgb) {
        for (int c : rgb) {
            int r = Palette.red(c);
            int g = Palette.green(c);
            int b = Palette.blue(c);
            int bin = ((r >> (8 - BITS)) << (2 * BITS)) | ((g >> (8 - BITS)) << BITS) | (b >> (8 - BITS));
            count[bin]++;
            sumRed[bin] += r;
            sumGreen[bin] += g;
            sumBlue[bin] += b;
        }
    }

    /** A palette of at most {@code maxColours} colours for everything added (black when nothing was). */
    public Palette palette(int maxColours) {
        List<Box> boxes = new ArrayList<>();
        Box all = new Box(occupiedBins());
        if (all.weight() == 0) return new Palette(new int[] {0});
        boxes.add(all);
        while (boxes.size() < maxColours) {
            Box worst = boxes.stream().filter(Box::splittable).max(Comparator.comparingDouble(Box::error)).orElse(null);
            if (worst == null) break;
            boxes.remove(worst);
            boxes.addAll(worst.split());
        }
        int[] colours = boxes.stream().mapToInt(Box::meanColour).sorted().toArray();
        return new Palette(colours);
    }

    private Bin[] occupiedBins() {
        List<Bin> bins = new ArrayList<>();
        for (int i = 0; i < BINS; i++) {
            if (count[i] > 0) {
                bins.add(new Bin(count[i], (double) sumRed[i] / count[i], (double) sumGreen[i] / count[i],
                        (double) sumBlue[i] / count[i]));
            }
        }
        return bins.toArray(Bin[]::new);
    }

    /** The pixels of one histogram bin: how many, and their mean colour. */
    private record Bin(long weight, double r, double g, double b) {
        double channel(int c) { return c == 0 ? r : c == 1 ? g : b; }
    }

    /** A set of bins that will become one palette entry. */
    private static final class Box {
        private final Bin[] bins;
        private final long weight;
        private final double[] mean = new double[3];
        private final double[] variance = new double[3];

        Box(Bin[] bins) {
            this.bins = bins;
            long w = 0;
            double[] sum = new double[3];
            double[] sumSquares = new double[3];
            for (Bin bin : bins) {
                w += bin.weight();
                for (int c = 0; c < 3; c++) {
                    double v = bin.channel(c);
                    sum[c] += bin.weight() * v;
                    sumSquares[c] += bin.weight() * v * v;
                }
            }
            weight = w;
            for (int c = 0; c < 3 && w > 0; c++) {
                mean[c] = sum[c] / w;
                variance[c] = Math.max(0, sumSquares[c] - sum[c] * mean[c]);
            }
        }

        long weight() { return weight; }

        /** The squared distance of every pixel to the box's mean. */
        double error() { return variance[0] + variance[1] + variance[2]; }

        boolean splittable() { return bins.length > 1 && error() > 0; }

        /** Two boxes, cut at the weighted median along the channel that varies most. */
        List<Box> split() {
            int axis = variance[0] >= variance[1] && variance[0] >= variance[2] ? 0 : variance[1] >= variance[2] ? 1 : 2;
            Bin[] sorted = bins.clone();
            Arrays.sort(sorted, Comparator.comparingDouble((Bin b) -> b.channel(axis))
                    .thenComparingDouble(Bin::r).thenComparingDouble(Bin::g).thenComparingDouble(Bin::b));
            long half = 0;
            int cut = 1;
            for (int i = 0; i < sorted.length - 1; i++) {
                half += sorted[i].weight();
                cut = i + 1;
                if (2 * half >= weight) break;
            }
            return List.of(new Box(Arrays.copyOfRange(sorted, 0, cut)), new Box(Arrays.copyOfRange(sorted, cut, sorted.length)));
        }

        int meanColour() {
            int r = (int) Math.round(mean[0]);
            int g = (int) Math.round(mean[1]);
            int b = (int) Math.round(mean[2]);
            return (r << 16) | (g << 8) | b;
        }
    }
}
