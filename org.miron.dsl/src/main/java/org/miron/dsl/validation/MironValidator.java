package org.miron.dsl.validation;

import static org.miron.dsl.validation.MironIssueCodes.*;
import static org.miron.dsl.validation.Texts.line;

import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.ServiceLoader;

import org.eclipse.xtext.validation.Check;
import org.eclipse.xtext.validation.CheckType;
import org.eclipse.xtext.validation.ComposedChecks;
import org.miron.dsl.miron.MironModel;
import org.miron.dsl.miron.MironPackage;
import org.miron.dsl.miron.Requirement;
import org.miron.dsl.miron.Rule;
import org.miron.dsl.roqme.Import;
import org.miron.dsl.roqme.RoqmeModel;
import org.miron.dsl.util.Imports;

/**
 * MIRoN's checks on top of RoQME's (inherited, with RoQME's composed check sets): imports of
 * .bt/.roqme/.miron files with distinct aliases here; varpoint types, bindings and rules in the
 * composed check sets.
 */
@ComposedChecks(validators = { VariationPointTypeChecks.class, BindingChecks.class, RuleChecks.class,
        RequirementChecks.class })
public class MironValidator extends AbstractMironValidator {

    private static final MironPackage M = MironPackage.eINSTANCE;
    /**
     * Rule interaction checks on the class path (org.miron.generator's), if any; none when the
     * system property miron.ruleAnalysis is "false" (the launcher's AppCDS training run: JDK 17's
     * archive dump crashes on a class the analysis loads, see docs/performance.md).
     */
    private static final List<RuleAnalysis> RULE_ANALYSES = "false".equals(System.getProperty("miron.ruleAnalysis"))
            ? List.of()
            : ServiceLoader.load(RuleAnalysis.class, MironValidator.class.getClassLoader()).stream()
                    .map(ServiceLoader.Provider::get).toList();

    @Override
    protected List<String> allowedImports() {
        // BehaviorTree.CPP's own trees are .xml files (root element <root>), loaded by the BT language.
        return List.of("bt", "xml", "roqme", "miron");
    }

    /**
     * Rules that can apply together and cannot hold together, rules that never apply, rules always
     * overridden, requirements that can never be violated or never be met (docs/issue-codes.md):
     * warnings on the rules and requirements of this file, only when the file has
     * no syntax error (the analysis itself skips models the generators would refuse). Expensive
     * (up to its 1 s budget): `miron check` and the language server run it, `miron generate` does not.
     */
    @Check(CheckType.EXPENSIVE)
    public void checkRuleInteractions(MironModel model) {
        if (RULE_ANALYSES.isEmpty() || model.eResource() == null || !model.eResource().getErrors().isEmpty()
                || model.getSentences().stream().noneMatch(s -> s instanceof Rule || s instanceof Requirement)) {
            return;
        }
        for (RuleAnalysis analysis : RULE_ANALYSES) {
            for (RuleAnalysis.Finding f : analysis.analyse(model)) {
                if (f.element().eResource() == model.eResource()) {
                    warning(f.message(), f.element(), f.element().eClass().getEStructuralFeature("name"), f.code());
                }
            }
        }
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

    /**
     * The nominal tree is the imported BT file that names its main tree, else the first one
     * (as the weaver chooses). A file of several trees without main_tree_to_execute is a fine
     * include library by itself, but as the nominal tree it leaves the main tree unknown.
     */
    @Check
    public void checkNominalTreeHasAMainTree(RoqmeModel model) {
        Import first = null;
        for (Import imp : model.getImports()) {
            org.eclipse.emf.ecore.resource.Resource resource = Imports.load(imp);
            if (resource != null && !resource.getContents().isEmpty()
                    && resource.getContents().get(0) instanceof org.miron.bt.bt.BTModel bt) {
                if (bt.getMain_tree_to_execute() != null) {
                    return;
                }
                if (first == null) {
                    first = imp;
                }
            }
        }
        org.miron.bt.bt.BTModel nominal = first == null ? null
                : (org.miron.bt.bt.BTModel) Imports.load(first).getContents().get(0);
        if (nominal != null && nominal.getTrees().size() > 1) {
            error(first.getImportURI() + " holds " + nominal.getTrees().size() + " trees and no main_tree_to_execute: "
                    + "the woven tree needs to know which one is the main tree (set main_tree_to_execute there)",
                    first, null, NOMINAL_TREE_WITHOUT_MAIN);
        }
    }
}
