package org.miron.diagram;

import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Optional;
import java.util.Set;

/**
 * A diagram before layout: its frames (trees) and the links between them (a SubTree call, a
 * variant that puts a tree in place), drawn as edges between the frames.
 */
public final class Diagram {
    /** An edge between two frames: {@code edge:call} or {@code edge:variant}. */
    public record Link(String from, String to, String type) {
    }

    private final String title;
    private final List<Frame> frames = new ArrayList<>();
    private final Set<Link> links = new LinkedHashSet<>();

    public Diagram(String title) {
        this.title = title;
    }

    public String title() {
        return title;
    }

    public List<Frame> frames() {
        return frames;
    }

    public Set<Link> links() {
        return links;
    }

    public Optional<Frame> frame(String id) {
        return frames.stream().filter(f -> f.id().equals(id)).findFirst();
    }

    /** Every node of every frame. */
    public List<Shape> shapes() {
        List<Shape> all = new ArrayList<>();
        frames.forEach(f -> all.addAll(f.shapes()));
        return all;
    }
}
