/**
 * Keeps one core busy for the given number of seconds, as another JVM at work on a shared machine
 * would (arithmetic and a little allocation on one thread): the load of `compile-speed.sh --busy`.
 * java bench/tools/BusyCore.java SECONDS
 */
public class BusyCore {
    public static void main(String[] args) {
        long end = System.nanoTime() + (long) (Double.parseDouble(args[0]) * 1e9);
        double sum = 0;
        double[][] kept = new double[4096][];
        for (long round = 0; System.nanoTime() < end; round++) {
            for (int i = 0; i < 100_000; i++) sum += Math.sqrt(i + sum);
            kept[(int) (round & 4095)] = new double[64];
        }
        System.out.println(sum > 0 ? "done" : "");
    }
}
