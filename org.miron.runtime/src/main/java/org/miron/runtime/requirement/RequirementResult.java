package org.miron.runtime.requirement;

import java.util.List;

/**
 * A requirement over one run: its verdict, how many times it was violated (for an {@code always}:
 * each time its body turned false), the first violation, since when an obligation was open at the
 * end (-1: none) and the signals that never had a value.
 */
public record RequirementResult(String name, Verdict verdict, int violations, RequirementEvent firstViolation,
        long openSinceMs, List<String> neverValued) {
}
