package org.miron.diagram;

import java.util.Locale;

/**
 * `gradle :org.miron.diagram:benchmark`: lays out a generated tree of 500 nodes (controls with
 * three to five children, decorators, actions with ports) and prints the time of each run and the
 * median after warm-up. Numbers in docs/performance.md; nothing is asserted.
 */
public final class LayoutBenchmark {
    private LayoutBenchmark() {
    }

    public static void main(String[] args) {
        int size = args.length > 0 ? Integer.parseInt(args[0]) : 500;
        Diagram diagram = generated(size);
        int nodes = diagram.shapes().size();
        long[] times = new long[15];
        for (int run = 0; run < times.length; run++) {
            long start = System.nanoTime();
            Diagrams.svg(diagram);
            times[run] = System.nanoTime() - start;
        }
        long first = times[0];
        java.util.Arrays.sort(times, 5, times.length);
        System.out.printf(Locale.ROOT, "layout+svg of a %d-node tree: first run %.0f ms, median after warm-up %.0f ms, "
                + "best %.0f ms%n", nodes, first / 1e6, times[10] / 1e6, times[5] / 1e6);
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
