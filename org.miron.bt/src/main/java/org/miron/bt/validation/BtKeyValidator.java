package org.miron.bt.validation;

import java.util.Comparator;
import java.util.List;

import org.eclipse.xtext.validation.AbstractDeclarativeValidator;
import org.eclipse.xtext.validation.Check;
import org.eclipse.xtext.validation.EValidatorRegistrar;
import org.miron.bt.bt.BTModel;
import org.miron.bt.bt.BtPackage;
import org.miron.bt.util.Suggestions;

/**
 * Blackboard keys: a port that reads a key nothing in the file or its includes writes, while a
 * written key has a near-identical name, is most likely a typo ({@code {targte}} beside
 * {@code target}); at run time it has no value and its node fails. A key that is only read is no
 * warning by itself: host applications set keys from code.
 */
public class BtKeyValidator extends AbstractDeclarativeValidator {

    @Override
    public void register(EValidatorRegistrar registrar) {
        // a part of BtValidator (ComposedChecks), not a validator of its own
    }

    @Check
    public void checkKeyTypos(BTModel model) {
        if (model.eResource() == null) {
            return;
        }
        BlackboardKeys keys = BlackboardKeys.of(model.eResource());
        for (BlackboardKeys.Read read : keys.reads()) {
            if (read.attribute().eResource() != model.eResource() || keys.written().contains(read.key())) {
                continue;
            }
            List<String> near = keys.written().stream().filter(w -> Suggestions.isTypo(read.key(), w))
                    .sorted(Comparator.comparingInt((String w) -> Suggestions.distance(read.key(), w))
                            .thenComparing(w -> w))
                    .limit(Suggestions.MAX).toList();
            if (!near.isEmpty()) {
                warning("nothing in this file or its includes writes blackboard key '" + read.key() + "': did you mean '"
                        + near.get(0) + "'?", read.attribute(), BtPackage.eINSTANCE.getAttribute_Value(),
                        BtIssueCodes.KEY_TYPO, near.toArray(new String[0]));
            }
        }
    }
}
