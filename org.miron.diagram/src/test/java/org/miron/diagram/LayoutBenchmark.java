package org.miron.diagram;

import java.util.Locale;

/**
 * `gradle :org.miron.diagram:benchmark`: lays out a generated tree of 500 nodes (controls with
 * three to five children, decorators, actions with ports) 25 times and prints the layout time of
 * the first (cold) run, the median and 90th percentile after warm-up, and the SVG writing time. Numbers in docs/performance.md; nothing is asserted.
 */
public final class LayoutBenchmark {
    private LayoutBenchmark() {
    }

    public static void main(String[] args) {
        int size = args.length > 0 ? Integer.parseInt(args[0]) : 500;
        Diagram diagram = generated(size);
        int nodes = diagram.shapes().size();
        // ELK's start-up (its option registry, the layered algorithm's classes) on a 3-node tree first,
        // so the cold 500-node run below measures the layout, not the loading.
        long boot = System.nanoTime();
        DiagramLayout.layout(generated(3));
        System.out.printf(Locale.ROOT, "ELK start-up (first layout of a 3-node tree in this JVM): %.0f ms%n",
                (System.nanoTime() - boot) / 1e6);
        int runs = 25;
        int warmUp = 5;
        long[] layout = new long[runs];
        long[] svg = new long[runs];
        for (int run = 0; run < runs; run++) {
            long start = System.nanoTime();
            org.eclipse.sprotty.SGraph graph = DiagramLayout.layout(diagram);
            long laidOut = System.nanoTime();
            SvgWriter.write(graph);
            layout[run] = laidOut - start;
            svg[run] = System.nanoTime() - laidOut;
        }
        System.out.printf(Locale.ROOT, "%d-node tree (load average %.1f): layout first run %.0f ms; "
                + "after %d warm-up runs: layout median %.0f ms, p90 %.0f ms; SVG writing median %.1f ms%n", nodes,
                java.lang.management.ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage(), layout[0] / 1e6,
                warmUp, percentile(layout, warmUp, 0.5), percentile(layout, warmUp, 0.9), percentile(svg, warmUp, 0.5));
        // The examples as `miron render` draws them (every tree, and the run-time view of the main tree).
        for (String example : new String[] { "intralogistics/intralogistics.miron", "hospital-delivery/hospital.miron" }) {
            org.eclipse.emf.ecore.resource.Resource model = Models.example(example);
            Diagram all = Diagrams.of(model, null);
            long[] times = new long[15];
            for (int run = 0; run < times.length; run++) {
                long start = System.nanoTime();
                DiagramLayout.layout(all);
                times[run] = System.nanoTime() - start;
            }
            System.out.printf(Locale.ROOT, "%s: %d nodes in %d frames, layout median %.1f ms after warm-up%n", example,
                    all.shapes().size(), all.frames().size(), percentile(times, warmUp, 0.5));
        }
    }

    private static double percentile(long[] times, int from, double p) {
        long[] sorted = java.util.Arrays.copyOfRange(times, from, times.length);
        java.util.Arrays.sort(sorted);
        return sorted[(int) Math.min(sorted.length - 1, Math.round(p * (sorted.length - 1)))] / 1e6;
    }

    /** A bushy tree of {@code size} nodes, deterministic. */
    static Diagram generated(int size) {
        Diagram diagram = new Diagram("generated");
        Frame frame = new Frame("tree:Generated", "Generated");
        Shape root = new Shape("0", ShapeKind.CONTROL, "root", "Sequence");
        frame.roots().add(root);
        java.util.ArrayDeque<Shape> open = new java.util.ArrayDeque<>();
        open.add(root);
        int made = 1;
        int k = 0;
        while (made < size && !open.isEmpty()) {
            Shape parent = open.poll();
            int children = parent.kind() == ShapeKind.DECORATOR ? 1 : 3 + (k++ % 3);
            for (int i = 0; i < children && made < size; i++, made++) {
                ShapeKind kind = switch (made % 4) {
                    case 0 -> ShapeKind.CONTROL;
                    case 1 -> ShapeKind.DECORATOR;
                    default -> made % 3 == 0 ? ShapeKind.CONDITION : ShapeKind.ACTION;
                };
                Shape child = new Shape(parent.id() + "." + i, kind, kind.word() + "_" + made, kind.word());
                if (kind == ShapeKind.ACTION) {
                    child.ports().add(new Shape.Port("goal", "{target_" + made + "}", null));
                }
                parent.children().add(child);
                if (kind == ShapeKind.CONTROL || kind == ShapeKind.DECORATOR) {
                    open.add(child);
                }
            }
        }
        diagram.frames().add(frame);
        return diagram;
    }
}
