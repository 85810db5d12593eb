package org.miron.runtime.sim;

import java.util.List;

/** A world file that cannot be simulated: every problem, one line each ({@code file:line:col: error [code]: message}). */
public final class WorldException extends Exception {
    private static final long serialVersionUID = 1L;
    private final List<String> problems;

    public WorldException(List<String> problems) {
        super(String.join("\n", problems));
        this.problems = List.copyOf(problems);
    }

    public List<String> problems() {
        return problems;
    }
}
