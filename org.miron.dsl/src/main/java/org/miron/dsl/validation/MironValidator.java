package org.miron.dsl.validation;

import static org.miron.dsl.validation.MironIssueCodes.*;
import static org.miron.dsl.validation.Texts.line;

import java.util.HashMap;
import java.util.List;
import java.util.Map;

import org.eclipse.xtext.validation.Check;
import org.eclipse.xtext.validation.ComposedChecks;
import org.miron.dsl.miron.MironPackage;
import org.miron.dsl.roqme.Import;
import org.miron.dsl.roqme.RoqmeModel;
import org.miron.dsl.util.Imports;

/**
 * MIRoN's checks on top of RoQME's (inherited, with RoQME's composed check sets): imports of
 * .bt/.roqme/.miron files with distinct aliases here; varpoint types, bindings and rules in the
 * composed check sets.
 */
@ComposedChecks(validators = { VarpointTypeChecks.class, BindingChecks.class, RuleChecks.class })
public class MironValidator extends AbstractMironValidator {

    private static final MironPackage M = MironPackage.eINSTANCE;

    @Override
    protected List<String> allowedImports() {
        return List.of("bt", "roqme", "miron");
    }

    @Check
    public void checkAliases(RoqmeModel model) {
        Map<String, Import> seen = new HashMap<>();
        for (Import imp : model.getImports()) {
            String alias = Imports.aliasOf(imp);
            if (alias != null && seen.putIfAbsent(alias, imp) != null) {
                error("alias '" + alias + "' is already used by the import at line " + line(seen.get(alias)), imp,
                        M.getImport_Alias(), DUPLICATE_ALIAS, alias);
            }
        }
    }
}
