import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import java.util.TreeMap;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Compares two HotSpot compilation logs (-XX:+UnlockDiagnosticVMOptions -XX:+LogCompilation) of
 * the same render: per method of a package, the machine code size of its last C2 (tier 4, not OSR)
 * compilation and how many profiled conditional branches C2 parsed into it, inlined callees
 * included. A test C2 folds away (a static final switched off) leaves no branch record and no code.
 * java bench/tools/JitBranches.java A.log B.log [PACKAGE_PREFIX]
 */
public class JitBranches {
    private static final Pattern METHOD = Pattern.compile("method='([^']*)'");
    private static final Pattern LEVEL = Pattern.compile("level='(\\d)'");
    private static final Pattern NMSIZE = Pattern.compile("nmsize='(\\d+)'");

    public static void main(String[] a) throws Exception {
        String prefix = a.length > 2 ? a[2] : "dev.crt.render.";
        Map<String, int[]> x = tasks(Path.of(a[0]), prefix), y = tasks(Path.of(a[1]), prefix);
        System.out.printf("%-64s %9s %9s %9s %9s%n", "method (last C2 compilation)", "A bytes", "B bytes", "A branch", "B branch");
        int[] sum = new int[4];
        for (var e : x.entrySet()) {
            int[] p = e.getValue(), q = y.get(e.getKey());
            if (q == null) continue;
            String name = e.getKey().replace("&lt;", "<").replace("&gt;", ">");
            name = name.substring(prefix.length(), name.indexOf(' ', name.indexOf(' ') + 1));
            if (p[0] == q[0] && p[1] == q[1]) continue;
            System.out.printf("%-64s %9d %9d %9d %9d%n", name, p[0], q[0], p[1], q[1]);
            sum[0] += p[0];
            sum[1] += q[0];
            sum[2] += p[1];
            sum[3] += q[1];
        }
        System.out.printf("%-64s %9d %9d %9d %9d%n", "(the methods that differ)", sum[0], sum[1], sum[2], sum[3]);
    }

    /** Per method: {machine code bytes, branch records} of its last C2 compilation. */
    private static Map<String, int[]> tasks(Path log, String prefix) throws Exception {
        Map<String, int[]> out = new TreeMap<>();
        String method = null;
        boolean c2 = false;
        int branches = 0;
        for (String line : Files.readAllLines(log, java.nio.charset.StandardCharsets.ISO_8859_1)) {
            if (line.startsWith("<task ")) {
                Matcher m = METHOD.matcher(line), l = LEVEL.matcher(line);
                m.find();
                method = m.group(1);
                // C2's tasks carry no level attribute; C1's say level 1 to 3.
                c2 = !(l.find() && !l.group(1).equals("4")) && !line.contains("osr_bci");
                branches = 0;
            } else if (method != null && line.startsWith("<branch")) {
                branches++;
            } else if (method != null && line.startsWith("<task_done")) {
                Matcher n = NMSIZE.matcher(line);
                if (c2 && method.startsWith(prefix) && n.find()) out.put(method, new int[] {Integer.parseInt(n.group(1)), branches});
                method = null;
            }
        }
        return out;
    }
}
