package org.miron.cli;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * {@code gradle :org.miron.cli:renderStartup [-Pruns=N]}: a one-shot {@code ./miron render} of a
 * 459-node tree against {@code ./miron check} of the same file, each a fresh process as a user runs
 * it, interleaved; wall and CPU time per run and their medians, printed, never asserted
 * (docs/performance.md, "miron render start-up"). The first run of each trains the launcher's archive
 * when the build is new, so it is not counted.
 */
public final class RenderStartup {
    private static final Pattern TIMES = Pattern.compile("TIMES (\\S+) (\\S+) (\\S+)");

    private RenderStartup() {
    }

    public static void main(String[] args) throws Exception {
        Path root = Path.of(System.getProperty("miron.root"));
        int runs = Integer.getInteger("miron.benchmark.runs", 5);
        Path dir = Files.createTempDirectory("render-startup");
        Path tree = dir.resolve("big.xml");
        int nodes = BigTree.write(tree);
        System.out.printf("tree: %d nodes (%s); load average %s%n", nodes, tree, loadAverage());
        run(root, "check", tree, dir); // trains the archive once after a build; not counted
        run(root, "render", tree, dir);
        List<double[]> check = new ArrayList<>();
        List<double[]> render = new ArrayList<>();
        for (int i = 0; i < runs; i++) {
            check.add(run(root, "check", tree, dir));
            render.add(run(root, "render", tree, dir));
            System.out.printf("run %d: check %.2f s wall %.2f s CPU, render %.2f s wall %.2f s CPU%n", i + 1,
                    check.get(i)[0], check.get(i)[1], render.get(i)[0], render.get(i)[1]);
        }
        System.out.printf("median: check %.2f s wall %.2f s CPU; render %.2f s wall %.2f s CPU; render - check %.2f s wall%n",
                median(check, 0), median(check, 1), median(render, 0), median(render, 1),
                median(render, 0) - median(check, 0));
        System.out.printf("load average after: %s%n", loadAverage());
    }

    /** Wall and CPU (user + system) seconds of one `./miron COMMAND tree`, timed by bash's `time`. */
    private static double[] run(Path root, String command, Path tree, Path dir) throws IOException, InterruptedException {
        String out = command.equals("render") ? " -o " + dir.resolve("big.svg") : " > /dev/null";
        ProcessBuilder pb = new ProcessBuilder("bash", "-c", "TIMEFORMAT='TIMES %R %U %S'; time " + root.resolve("miron")
                + " " + command + " " + tree + out);
        pb.redirectErrorStream(true);
        Process p = pb.start();
        String text = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        if (p.waitFor() != 0) {
            throw new IllegalStateException("miron " + command + " failed:\n" + text);
        }
        Matcher m = TIMES.matcher(text);
        if (!m.find()) {
            throw new IllegalStateException("no times from bash:\n" + text);
        }
        return new double[] { Double.parseDouble(m.group(1)), Double.parseDouble(m.group(2)) + Double.parseDouble(m.group(3)) };
    }

    private static double median(List<double[]> values, int column) {
        double[] v = values.stream().mapToDouble(a -> a[column]).sorted().toArray();
        return v.length % 2 == 1 ? v[v.length / 2] : (v[v.length / 2 - 1] + v[v.length / 2]) / 2;
    }

    private static String loadAverage() throws IOException {
        return Files.readString(Path.of("/proc/loadavg")).trim();
    }

    /** A version-4 tree of 459 nodes: controls of three or four children five levels deep, leaves padded out. */
    static final class BigTree {
        private int count;

        static int write(Path file) throws IOException {
            BigTree t = new BigTree();
            StringBuilder body = new StringBuilder();
            for (int i = 0; i < 2; i++) {
                t.node(1, body);
            }
            StringBuilder tail = new StringBuilder();
            while (t.count + 2 < 459) {
                t.count++;
                tail.append("<IsBatteryLow name=\"pad").append(t.count).append("\"/>\n");
            }
            Files.writeString(file, "<?xml version=\"1.0\"?>\n<root BTCPP_format=\"4\" main_tree_to_execute=\"Main\">\n"
                    + "<BehaviorTree ID=\"Main\">\n<Sequence name=\"root\">\n" + body + "<Sequence name=\"tail\">\n" + tail
                    + "</Sequence>\n</Sequence>\n</BehaviorTree>\n<TreeNodesModel>\n"
                    + "<Action ID=\"MoveTo\"><input_port name=\"x\"/><input_port name=\"y\"/></Action>\n"
                    + "<Condition ID=\"IsBatteryLow\"/>\n</TreeNodesModel>\n</root>\n", StandardCharsets.UTF_8);
            return t.count + 2;
        }

        private void node(int depth, StringBuilder out) {
            int i = ++count;
            if (depth >= 5) {
                out.append(i % 2 == 1 ? "<MoveTo name=\"move" + i + "\" x=\"" + i + "\" y=\"1\"/>\n"
                        : "<IsBatteryLow name=\"low" + i + "\"/>\n");
                return;
            }
            if (depth == 3 && i % 4 == 0) {
                out.append("<Inverter>\n");
                node(depth + 1, out);
                out.append("</Inverter>\n");
                return;
            }
            String kind = List.of("Sequence", "Fallback", "ReactiveSequence").get(i % 3);
            out.append('<').append(kind).append(" name=\"").append(kind.toLowerCase()).append(i).append("\">\n");
            for (int c = 0; c < 3 + (i % 3 == 0 ? 1 : 0); c++) {
                node(depth + 1, out);
            }
            out.append("</").append(kind).append(">\n");
        }
    }
}
