package dev.crt.lang.eval;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Locale;
import java.util.Random;
import org.junit.jupiter.api.Test;

class DecimalsTest {
    @Test
    void everyFormOfTheGrammarsFloatReadsToTheJdksDoubleBitForBit() {
        Random random = new Random(11);
        String[] fixed = {"0.0", "0.", ".5", "1.", "00.000", "1e0", "1E+22", "1e23", "9007199254740993.0", "123456789012345.6",
            "0.1", "0.3", "2.5e-3", "1.7976931348623157e308", "4.9e-324", "1e-400", "1e400", ".000000000000000000000001",
            "999999999999999.0", "1000000000000000.0", "3.141593", "1.5e", "1..2"};
        for (String s : fixed) check(s);
        for (int i = 0; i < 300_000; i++) {
            StringBuilder b = new StringBuilder();
            int whole = random.nextInt(12), frac = random.nextInt(12);
            for (int k = 0; k < whole; k++) b.append((char) ('0' + random.nextInt(10)));
            if (whole == 0 || random.nextBoolean()) {
                b.append('.');
                if (whole == 0 && frac == 0) frac = 1;
                for (int k = 0; k < frac; k++) b.append((char) ('0' + random.nextInt(10)));
            }
            if (random.nextInt(3) == 0) {
                b.append(random.nextBoolean() ? 'e' : 'E');
                int r = random.nextInt(3);
                if (r == 1) b.append('+');
                if (r == 2) b.append('-');
                b.append(random.nextInt(random.nextBoolean() ? 30 : 400));
            }
            check(b.toString());
            check(String.format(Locale.ROOT, "%.6f", random.nextDouble() * 40 - 20).replace("-", ""));
        }
    }

    private static void check(String s) {
        double expected;
        try {
            expected = Double.parseDouble(s);
        } catch (NumberFormatException e) {
            try {
                Decimals.parse(s);
            } catch (NumberFormatException fine) {
                return;
            }
            throw new AssertionError("'" + s + "' is no number, yet it was read");
        }
        assertThat(Double.doubleToRawLongBits(Decimals.parse(s))).as("'%s'", s).isEqualTo(Double.doubleToRawLongBits(expected));
    }
}
