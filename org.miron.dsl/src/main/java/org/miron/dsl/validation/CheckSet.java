package org.miron.dsl.validation;

import org.eclipse.xtext.validation.AbstractDeclarativeValidator;
import org.eclipse.xtext.validation.EValidatorRegistrar;

/**
 * A group of checks composed into a language's validator with {@code @ComposedChecks}; it runs
 * as part of that validator and is never registered on its own.
 */
public abstract class CheckSet extends AbstractDeclarativeValidator {

    /** Set by tests: make every exception of a check visible instead of swallowing NPEs. */
    public static final String STRICT = "org.miron.dsl.strictValidation";

    @Override
    public void register(EValidatorRegistrar registrar) {
        // composed into RoqmeValidator / MironValidator, which are the registered ones
    }

    @Override
    protected void handleExceptionDuringValidation(Throwable t) {
        rethrowIfStrict(t);
        super.handleExceptionDuringValidation(t);
    }

    /** Xtext ignores NullPointerExceptions in checks; in strict mode (tests) they fail like anything else. */
    static void rethrowIfStrict(Throwable t) {
        if (Boolean.getBoolean(STRICT) && t instanceof NullPointerException) {
            throw (NullPointerException) t;
        }
    }
}
