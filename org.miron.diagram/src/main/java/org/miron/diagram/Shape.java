package org.miron.diagram;

import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

/**
 * One node of a diagram before layout: what it is, its labels and its children. Built by
 * {@link BtShapes} and {@link MironShapes}, laid out by {@link DiagramLayout}.
 */
public final class Shape {
    /** A port line, {@code name = value}, and the varpoint that sets it (null: none). */
    public record Port(String name, String value, String parameter) {
    }

    private final String id;
    private final ShapeKind kind;
    private final String title;
    private final String type;
    private final List<Port> ports = new ArrayList<>();
    private final List<String> notes = new ArrayList<>();
    private final Set<String> cssClasses = new LinkedHashSet<>();
    private final List<Shape> children = new ArrayList<>();
    /** The Sprotty type of the edge from the parent: edge:child, or edge:varpoint / edge:variant. */
    private String edgeType = "edge:child";
    /** The frame (tree) this node calls or puts in place, or null. */
    private String link;
    /** Where the node is written, or null. */
    private SourceSpan span;
    /** A SubTree call: whether the called tree is drawn below it; null for other nodes. */
    private Boolean expanded;

    public Shape(String id, ShapeKind kind, String title, String type) {
        this.id = id;
        this.kind = kind;
        this.title = title;
        this.type = type;
    }

    public String id() {
        return id;
    }

    public ShapeKind kind() {
        return kind;
    }

    /** The first line: the node's name, else its ID or tag. */
    public String title() {
        return title;
    }

    /** The second line: the node's type when the title is a name, else the kind. */
    public String type() {
        return type;
    }

    public List<Port> ports() {
        return ports;
    }

    /** Extra lines a MIRoN model adds (the varpoints bound here). */
    public List<String> notes() {
        return notes;
    }

    public Set<String> cssClasses() {
        return cssClasses;
    }

    public List<Shape> children() {
        return children;
    }

    public String edgeType() {
        return edgeType;
    }

    public Shape edgeType(String type) {
        this.edgeType = type;
        return this;
    }

    public String link() {
        return link;
    }

    public Shape link(String frameId) {
        this.link = frameId;
        return this;
    }

    /** Where the node is written: {@code file:line:col}, or null. */
    public String source() {
        return span == null ? null : span.where();
    }

    public SourceSpan span() {
        return span;
    }

    public Shape span(SourceSpan where) {
        this.span = where;
        return this;
    }

    public Boolean expanded() {
        return expanded;
    }

    public Shape expanded(Boolean drawnBelow) {
        this.expanded = drawnBelow;
        return this;
    }

    /** This node and every node below it, parents first. */
    public List<Shape> all() {
        List<Shape> result = new ArrayList<>();
        collect(this, result);
        return result;
    }

    private static void collect(Shape shape, List<Shape> into) {
        into.add(shape);
        shape.children.forEach(child -> collect(child, into));
    }
}
