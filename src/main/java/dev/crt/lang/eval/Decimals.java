package dev.crt.lang.eval;

/**
 * Reads the decimal numbers of scripts (digits, an optional fraction, an optional exponent) to the
 * same double as {@link Double#parseDouble}, quickly for the usual ones: when the digits make an
 * integer below 2^53 and the power of ten is at most 22, both are exact doubles and one division
 * or multiplication rounds correctly (Clinger's fast path). Anything else goes to the JDK.
 */
final class Decimals {
    private static final double[] POWERS = new double[23];

    static {
        double p = 1;
        for (int i = 0; i < POWERS.length; i++) {
            POWERS[i] = p;
            p *= 10;
        }
    }

    private Decimals() {}

    static double parse(String s) { return parse(s, 0, s.length()); }

    /** The number written in {@code s} from {@code from} to {@code to} (exclusive), without cutting it out. */
    static double parse(String s, int from, int to) {
        int n = to;
        long digits = 0;
        int significant = 0;
        int scale = 0;
        int i = from;
        boolean fraction = false;
        for (; i < n; i++) {
            char c = s.charAt(i);
            if (c >= '0' && c <= '9') {
                if (significant > 0 || c != '0') significant++;
                if (significant > 15) return Double.parseDouble(s.substring(from, to));
                digits = digits * 10 + (c - '0');
                if (fraction) scale--;
            } else if (c == '.' && !fraction) {
                fraction = true;
            } else {
                break;
            }
        }
        if (i < n) {
            char c = s.charAt(i);
            if (c != 'e' && c != 'E') return Double.parseDouble(s.substring(from, to));
            int j = i + 1;
            boolean negative = false;
            if (j < n && (s.charAt(j) == '+' || s.charAt(j) == '-')) negative = s.charAt(j++) == '-';
            if (j >= n || j + 3 < n) return Double.parseDouble(s.substring(from, to));
            int exponent = 0;
            for (; j < n; j++) {
                char d = s.charAt(j);
                if (d < '0' || d > '9') return Double.parseDouble(s.substring(from, to));
                exponent = exponent * 10 + (d - '0');
            }
            scale += negative ? -exponent : exponent;
        }
        if (digits == 0) return 0.0; // a token has no sign: zero is +0.0
        if (scale < -22 || scale > 22) return Double.parseDouble(s.substring(from, to));
        return scale < 0 ? digits / POWERS[-scale] : digits * POWERS[scale];
    }
}
