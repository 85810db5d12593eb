package org.miron.diagram;

import java.util.List;
import java.util.Locale;
import java.util.Map;

import org.eclipse.sprotty.Point;
import org.eclipse.sprotty.SEdge;
import org.eclipse.sprotty.SGraph;
import org.eclipse.sprotty.SLabel;
import org.eclipse.sprotty.SModelElement;
import org.eclipse.sprotty.SNode;

/**
 * A laid-out Sprotty model as one standalone SVG document: no script, no external resource, its
 * style inside (light and dark colours by {@code prefers-color-scheme}). Every node is a group
 * {@code <g class="node node-<kind> ..." data-id="...">} that pages can colour by its id (the live
 * monitor sets {@code status-<status>} classes); a node linked to a tree links to its frame. All
 * text is escaped and characters XML forbids are dropped, so the document is well-formed whatever
 * the model holds.
 */
public final class SvgWriter {
    /** The style of every diagram, for pages that embed several SVGs (they share it). */
    public static final String STYLE = """
            svg.miron-bt{--bg:#fff;--fg:#1d232a;--muted:#5b6570;--frame:#f6f8fa;--frame-line:#d0d7de;--edge:#57606a;
            --control:#dbeafe;--control-line:#1d4ed8;--decorator:#ede9fe;--decorator-line:#6d28d9;--action:#dcfce7;
            --action-line:#15803d;--condition:#fef9c3;--condition-line:#a16207;--subtree:#e0f2fe;--subtree-line:#0369a1;
            --builtin:#f3f4f6;--builtin-line:#6b7280;--varpoint:#ffedd5;--varpoint-line:#c2410c;--variant:#fff7ed;
            --variant-line:#ea580c;--woven:#0f766e;--running:#f59e0b;--success:#16a34a;--failure:#dc2626;--skipped:#9ca3af;
            background:var(--bg);font-family:'DejaVu Sans Mono',Menlo,Consolas,monospace}
            @media (prefers-color-scheme:dark){svg.miron-bt{--bg:#0d1117;--fg:#e6edf3;--muted:#9da7b3;--frame:#161b22;
            --frame-line:#30363d;--edge:#8b949e;--control:#172554;--control-line:#60a5fa;--decorator:#2e1065;
            --decorator-line:#a78bfa;--action:#052e16;--action-line:#4ade80;--condition:#422006;--condition-line:#facc15;
            --subtree:#082f49;--subtree-line:#38bdf8;--builtin:#1f2937;--builtin-line:#9ca3af;--varpoint:#431407;
            --varpoint-line:#fb923c;--variant:#2a1508;--variant-line:#fdba74;--woven:#2dd4bf}}
            svg.miron-bt text{fill:var(--fg);font-size:11px;white-space:pre}
            svg.miron-bt .label-title{font-size:12px;font-weight:bold}
            svg.miron-bt .label-type,svg.miron-bt .label-note{fill:var(--muted);font-style:italic}
            svg.miron-bt .label-heading{font-size:13px;font-weight:bold}
            svg.miron-bt .parameter{fill:var(--varpoint-line);font-weight:bold}
            svg.miron-bt .frame>rect{fill:var(--frame);stroke:var(--frame-line)}
            svg.miron-bt .node>.shape{stroke-width:1.5}
            svg.miron-bt .node-control>.shape{fill:var(--control);stroke:var(--control-line)}
            svg.miron-bt .node-decorator>.shape{fill:var(--decorator);stroke:var(--decorator-line)}
            svg.miron-bt .node-action>.shape{fill:var(--action);stroke:var(--action-line)}
            svg.miron-bt .node-condition>.shape{fill:var(--condition);stroke:var(--condition-line)}
            svg.miron-bt .node-subtree>.shape{fill:var(--subtree);stroke:var(--subtree-line)}
            svg.miron-bt .node-builtin>.shape{fill:var(--builtin);stroke:var(--builtin-line);stroke-dasharray:4 2}
            svg.miron-bt .node-varpoint>.shape{fill:var(--varpoint);stroke:var(--varpoint-line);stroke-dasharray:6 3}
            svg.miron-bt .node-variant>.shape{fill:var(--variant);stroke:var(--variant-line)}
            svg.miron-bt .woven>.shape{stroke:var(--woven);stroke-width:3}
            svg.miron-bt .varpoint-target>.shape{stroke:var(--varpoint-line);stroke-width:3.5}
            svg.miron-bt .active>.shape{stroke:var(--success);stroke-width:4}
            svg.miron-bt .inactive{opacity:.45}
            svg.miron-bt .status-running>.shape{stroke:var(--running);stroke-width:4}
            svg.miron-bt .status-success>.shape{stroke:var(--success);stroke-width:4}
            svg.miron-bt .status-failure>.shape{stroke:var(--failure);stroke-width:4}
            svg.miron-bt .status-skipped>.shape{stroke:var(--skipped);stroke-width:4;stroke-dasharray:2 2}
            svg.miron-bt .edge{fill:none;stroke:var(--edge);stroke-width:1.3}
            svg.miron-bt .edge-call,svg.miron-bt .edge-variant{stroke-dasharray:5 4;marker-end:url(#miron-arrow)}
            svg.miron-bt .edge-varpoint,svg.miron-bt .edge-variant{stroke:var(--varpoint-line)}
            svg.miron-bt #miron-arrow path{fill:var(--edge)}
            """;

    private SvgWriter() {
    }

    /** The SVG of a laid-out model. */
    public static String write(SGraph graph) {
        return write(graph, Map.of());
    }

    /** The SVG with extra classes on some nodes, by node id (e.g. {@code active}, {@code status-running}). */
    public static String write(SGraph graph, Map<String, List<String>> extraClasses) {
        double width = Math.ceil(size(graph, true)) + 1;
        double height = Math.ceil(size(graph, false)) + 1;
        StringBuilder svg = new StringBuilder(8192);
        svg.append("<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"miron-bt\" width=\"").append(num(width))
                .append("\" height=\"").append(num(height)).append("\" viewBox=\"0 0 ").append(num(width)).append(' ')
                .append(num(height)).append("\">\n<style>").append(STYLE).append("</style>\n")
                .append("<defs><marker id=\"miron-arrow\" viewBox=\"0 0 10 10\" refX=\"10\" refY=\"5\" markerWidth=\"8\" "
                        + "markerHeight=\"8\" orient=\"auto-start-reverse\"><path d=\"M0,0 L10,5 L0,10 z\"/></marker></defs>\n");
        for (SModelElement child : graph.getChildren()) {
            if (child instanceof SEdge edge) {
                edge(svg, edge);
            }
        }
        for (SModelElement child : graph.getChildren()) {
            if (child instanceof SNode frame) {
                frame(svg, frame, extraClasses);
            }
        }
        return svg.append("</svg>\n").toString();
    }

    private static double size(SGraph graph, boolean width) {
        if (graph.getSize() != null) {
            return width ? graph.getSize().getWidth() : graph.getSize().getHeight();
        }
        return 0;
    }

    private static void frame(StringBuilder svg, SNode frame, Map<String, List<String>> extra) {
        svg.append("<g class=\"frame\" id=\"").append(attr(frame.getId())).append("\" transform=\"translate(")
                .append(num(frame.getPosition().getX())).append(',').append(num(frame.getPosition().getY())).append(")\">\n")
                .append("<rect width=\"").append(num(frame.getSize().getWidth())).append("\" height=\"")
                .append(num(frame.getSize().getHeight())).append("\" rx=\"6\"/>\n");
        for (SModelElement child : frame.getChildren()) {
            if (child instanceof SLabel heading) {
                text(svg, heading, 13);
            } else if (child instanceof SEdge edge) {
                edge(svg, edge);
            }
        }
        for (SModelElement child : frame.getChildren()) {
            if (child instanceof SNode node) {
                node(svg, node, extra.getOrDefault(node.getId(), List.of()));
            }
        }
        svg.append("</g>\n");
    }

    private static void node(StringBuilder svg, SNode node, List<String> extra) {
        String kind = node.getType().substring(node.getType().indexOf(':') + 1);
        StringBuilder classes = new StringBuilder("node node-").append(kind);
        node.getCssClasses().forEach(c -> classes.append(' ').append(c));
        extra.forEach(c -> classes.append(' ').append(c));
        String link = node instanceof TreeSNode linked ? linked.getLink() : null;
        double w = node.getSize().getWidth();
        double h = node.getSize().getHeight();
        svg.append("<g class=\"").append(attr(classes.toString())).append("\" data-id=\"").append(attr(node.getId()))
                .append("\" data-kind=\"").append(kind).append('"');
        if (link != null) {
            svg.append(" data-link=\"").append(attr(link)).append('"');
        }
        if (node.getTrace() != null) {
            svg.append(" data-source=\"").append(attr(node.getTrace())).append('"');
        }
        svg.append(" transform=\"translate(").append(num(node.getPosition().getX())).append(',')
                .append(num(node.getPosition().getY())).append(")\">\n");
        if (node.getTrace() != null) {
            svg.append("<title>").append(text(node.getTrace())).append("</title>\n");
        }
        shape(svg, kind, w, h);
        if (link != null) {
            svg.append("<a href=\"#").append(attr(link)).append("\">");
        }
        for (SModelElement child : node.getChildren()) {
            if (child instanceof SLabel label) {
                text(svg, label, label.getType().equals("label:title") ? 12 : 11);
            }
        }
        if (link != null) {
            svg.append("</a>");
        }
        svg.append("</g>\n");
    }

    /** The outline of a kind: controls square, decorators with cut corners, conditions round, subtrees framed twice. */
    private static void shape(StringBuilder svg, String kind, double w, double h) {
        switch (kind) {
            case "decorator" -> svg.append(String.format(Locale.ROOT,
                    "<polygon class=\"shape\" points=\"8,0 %.1f,0 %.1f,8 %.1f,%.1f %.1f,%.1f 8,%.1f 0,%.1f 0,8\"/>\n",
                    w - 8, w, w, h - 8, w - 8, h, h, h - 8));
            case "subtree" -> svg.append(rect(w, h, 3)).append(String.format(Locale.ROOT,
                    "<rect x=\"3\" y=\"3\" width=\"%.1f\" height=\"%.1f\" rx=\"2\" fill=\"none\" stroke=\"var(--subtree-line)\"/>\n",
                    w - 6, h - 6));
            case "condition" -> svg.append(rect(w, h, Math.min(h / 2, 18)));
            case "control" -> svg.append(rect(w, h, 1));
            default -> svg.append(rect(w, h, 6));
        }
    }

    private static String rect(double w, double h, double rx) {
        return String.format(Locale.ROOT, "<rect class=\"shape\" width=\"%.1f\" height=\"%.1f\" rx=\"%.1f\"/>\n", w, h, rx);
    }

    private static void text(StringBuilder svg, SLabel label, int size) {
        String type = label.getType().substring(label.getType().indexOf(':') + 1);
        StringBuilder classes = new StringBuilder("label-").append(type);
        if (label.getCssClasses() != null) {
            label.getCssClasses().forEach(c -> classes.append(' ').append(c));
        }
        Point p = label.getPosition();
        svg.append("<text class=\"").append(attr(classes.toString())).append("\" x=\"").append(num(p.getX()))
                .append("\" y=\"").append(num(p.getY() + size)).append("\">").append(text(label.getText()))
                .append("</text>\n");
    }

    private static void edge(StringBuilder svg, SEdge edge) {
        List<Point> points = edge.getRoutingPoints();
        if (points == null || points.size() < 2) {
            return;
        }
        String type = edge.getType().substring(edge.getType().indexOf(':') + 1);
        StringBuilder d = new StringBuilder();
        for (Point p : points) {
            d.append(d.length() == 0 ? "M" : " L").append(num(p.getX())).append(',').append(num(p.getY()));
        }
        svg.append("<path class=\"edge edge-").append(attr(type)).append("\" data-source=\"").append(attr(edge.getSourceId()))
                .append("\" data-target=\"").append(attr(edge.getTargetId())).append("\" d=\"").append(d).append("\"/>\n");
    }

    private static String num(double value) {
        return value == Math.rint(value) ? Long.toString((long) value) : String.format(Locale.ROOT, "%.1f", value);
    }

    /** Text content: escaped, characters XML 1.0 forbids dropped. */
    static String text(String value) {
        StringBuilder out = new StringBuilder(value == null ? 0 : value.length());
        if (value == null) {
            return "";
        }
        value.codePoints().forEach(c -> {
            switch (c) {
                case '&' -> out.append("&amp;");
                case '<' -> out.append("&lt;");
                case '>' -> out.append("&gt;");
                case '"' -> out.append("&quot;");
                default -> {
                    if (c == 0x9 || c == 0xA || c == 0xD || c >= 0x20 && c <= 0xD7FF || c >= 0xE000 && c <= 0xFFFD
                            || c >= 0x10000 && c <= 0x10FFFF) {
                        out.appendCodePoint(c);
                    }
                }
            }
        });
        return out.toString();
    }

    private static String attr(String value) {
        return text(value).replace("\n", "&#10;").replace("\r", "&#13;").replace("\t", "&#9;");
    }
}
