package org.miron.executor.skills;

import java.util.Objects;
import org.miron.executor.ActionSpec;
import org.miron.executor.BtBuildException;
import org.miron.executor.Node;
import org.miron.executor.UnregisteredActionStrategy;

/** Fallback turning every unregistered action into push-skill requests through a {@link SkillClient}. */
public final class SkillActionStrategy implements UnregisteredActionStrategy {
    private final SkillClient client;

    public SkillActionStrategy(SkillClient client) {
        this.client = Objects.requireNonNull(client);
    }

    @Override
    public Node create(ActionSpec spec) {
        if (spec.kind() == ActionSpec.Kind.CONDITION) {
            // a skill may run for several ticks, a condition must answer at once
            throw new BtBuildException(spec.info().path() + ": condition '" + spec.id()
                    + "' is not registered; conditions must be registered Java conditions, not skills");
        }
        return new SkillActionNode(spec.info(), spec.id(), client, spec.outputPorts());
    }
}
