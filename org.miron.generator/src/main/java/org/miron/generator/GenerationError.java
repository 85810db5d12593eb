package org.miron.generator;

import org.eclipse.emf.ecore.EObject;

/**
 * A model the validators accept but the generators cannot translate (e.g. a rule reading a
 * timer): reported at the element's position like any validation error, and nothing is written.
 * code is a stable issue code (docs/issue-codes.md) when the problem has one, else null.
 */
public record GenerationError(EObject source, String message, String code) {

    public GenerationError(EObject source, String message) {
        this(source, message, null);
    }
}
