package org.miron.generator;

import org.eclipse.emf.ecore.EObject;

/**
 * A model the validators accept but the generators cannot translate (e.g. a rule reading a
 * timer): reported at the element's position like any validation error, and nothing is written.
 */
public record GenerationError(EObject source, String message) {
}
