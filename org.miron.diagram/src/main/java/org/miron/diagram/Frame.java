package org.miron.diagram;

import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

/** One tree of a diagram: a titled box holding its nodes, laid out on its own. */
public final class Frame {
    private final String id;
    private final String title;
    private final List<Shape> roots = new ArrayList<>();
    private final Set<String> cssClasses = new LinkedHashSet<>();

    public Frame(String id, String title) {
        this.id = id;
        this.title = title;
    }

    /** {@code tree:<ID>}: how node links and edges between frames name it. */
    public String id() {
        return id;
    }

    public String title() {
        return title;
    }

    public List<Shape> roots() {
        return roots;
    }

    public Set<String> cssClasses() {
        return cssClasses;
    }

    /** Every node of the frame, parents first. */
    public List<Shape> shapes() {
        List<Shape> all = new ArrayList<>();
        roots.forEach(root -> all.addAll(root.all()));
        return all;
    }
}
