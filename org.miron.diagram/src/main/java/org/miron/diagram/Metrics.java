package org.miron.diagram;

/**
 * How much room text takes, without a browser or AWT: the SVG sets its text in a monospace font
 * (0.6 em a character), so a width is a count of characters. Lines are 14 px apart.
 */
final class Metrics {
    static final double TITLE_CHAR = 7.2;   // 12 px bold monospace
    static final double SMALL_CHAR = 6.6;   // 11 px monospace
    static final double LINE = 14;
    static final double PAD_X = 10;
    static final double PAD_Y = 6;
    static final double MIN_WIDTH = 80;
    /** A frame's heading: its room above the nodes, and its characters' width. */
    static final double HEADING = 30;
    static final double HEADING_CHAR = 7.8; // 13 px bold monospace

    private Metrics() {
    }

    static double width(Shape shape) {
        double text = shape.title().length() * TITLE_CHAR;
        text = Math.max(text, shape.type().length() * SMALL_CHAR);
        for (String line : lines(shape)) {
            text = Math.max(text, line.length() * SMALL_CHAR);
        }
        return Math.ceil(Math.max(MIN_WIDTH, text + 2 * PAD_X));
    }

    static double height(Shape shape) {
        return 2 * PAD_Y + LINE * (2 + lines(shape).size()) + 2;
    }

    /** The lines under title and type: ports, then notes. */
    static java.util.List<String> lines(Shape shape) {
        java.util.List<String> lines = new java.util.ArrayList<>();
        for (Shape.Port port : shape.ports()) {
            lines.add(port.name() + " = " + port.value() + (port.parameter() == null ? "" : " ← " + port.parameter()));
        }
        lines.addAll(shape.notes());
        return lines;
    }

    static double headingWidth(String title) {
        return Math.ceil(title.length() * HEADING_CHAR + 2 * PAD_X);
    }
}
