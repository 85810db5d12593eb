package org.miron.executor;

import org.miron.executor.skills.SkillActionStrategy;

/**
 * What to do with an action ID nothing is registered for, e.g. turn it into push-skill requests
 * ({@link SkillActionStrategy}). The default refuses to build the tree.
 */
@FunctionalInterface
public interface UnregisteredActionStrategy {

    UnregisteredActionStrategy REJECT = spec -> {
        throw new BtBuildException(spec.info().path() + ": no " + spec.kind().name().toLowerCase()
                + " is registered for ID '" + spec.id() + "' (register it, or set a fallback strategy such as skills)");
    };

    Node create(ActionSpec spec);
}
