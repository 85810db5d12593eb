package org.miron.runtime.engine;

/**
 * A rule of {@code name.io.json}'s {@code rules}, listed in priority order (the first declared is
 * the most important).
 *
 * @param keep the boolean parameter that keeps the rule (true) or drops it for higher ones (false)
 */
public record RuleSpec(String name, String keep) {
}
