package org.miron.bt.tests;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.io.File;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.xtext.AbstractRule;
import org.eclipse.xtext.Assignment;
import org.eclipse.xtext.Grammar;
import org.eclipse.xtext.GrammarUtil;
import org.eclipse.xtext.Keyword;
import org.eclipse.xtext.ParserRule;
import org.eclipse.xtext.RuleCall;
import org.eclipse.xtext.diagnostics.Severity;
import org.eclipse.xtext.resource.XtextResource;
import org.eclipse.xtext.validation.Issue;
import org.junit.Test;
import org.miron.bt.bt.ControlNode;
import org.miron.bt.bt.DecoratorNode;
import org.miron.bt.bt.LeafNode;
import org.miron.bt.bt.SubtreeNode;
import org.miron.bt.bt.TreeNode;
import org.miron.bt.nodes.BuiltinNodes;
import org.miron.bt.nodes.NodeCatalogue;
import org.miron.bt.nodes.NodeModel;
import org.miron.bt.nodes.PortModel;
import org.miron.bt.services.BtGrammarAccess;

/**
 * The grammar and the catalogue of built-ins name the same elements: the keywords of Bt.xtext's
 * ElementKeyword rule (read from the grammar model, not copied) and the keywords its node rules
 * assign to {@code tag} are exactly the catalogue's tags and spellings; and every catalogue entry,
 * written with its required ports and fewest children, parses into the metamodel family of its
 * kind and validates without error in each version that has it.
 */
public class CatalogueGrammarTest {
    private static final Grammar GRAMMAR = BtFiles.INJECTOR.getInstance(BtGrammarAccess.class).getGrammar();

    /** The keywords of a rule and of the rules it calls (ElementKeyword calls V4ElementKeyword). */
    private static Set<String> keywordsOf(AbstractRule rule, Set<AbstractRule> seen) {
        Set<String> keywords = new TreeSet<>();
        if (!seen.add(rule)) {
            return keywords;
        }
        GrammarUtil.containedKeywords(rule.getAlternatives()).forEach(k -> keywords.add(k.getValue()));
        for (RuleCall call : GrammarUtil.containedRuleCalls(rule.getAlternatives())) {
            if (call.getRule() instanceof ParserRule) {
                keywords.addAll(keywordsOf(call.getRule(), seen));
            }
        }
        return keywords;
    }

    /** Every keyword a parser rule assigns to a node's tag, e.g. {@code tag='Switch3'}. */
    private static Set<String> assignedTags() {
        Set<String> tags = new TreeSet<>();
        for (ParserRule rule : GrammarUtil.allParserRules(GRAMMAR)) {
            for (Assignment assignment : GrammarUtil.containedAssignments(rule.getAlternatives())) {
                if (assignment.getFeature().equals("tag") && assignment.getTerminal() instanceof Keyword keyword) {
                    tags.add(keyword.getValue());
                }
            }
        }
        return tags;
    }

    private static void assertSame(String what, Set<String> grammar, Set<String> catalogue) {
        Set<String> notInCatalogue = new TreeSet<>(grammar);
        notInCatalogue.removeAll(catalogue);
        Set<String> notInGrammar = new TreeSet<>(catalogue);
        notInGrammar.removeAll(grammar);
        assertTrue(what + " without a catalogue entry (add them to BuiltinNodes): " + notInCatalogue,
                notInCatalogue.isEmpty());
        assertTrue("catalogue tags the grammar does not know as " + what + " (add them to Bt.xtext): " + notInGrammar,
                notInGrammar.isEmpty());
    }

    @Test
    public void elementKeywordsAreTheCatalogueTags() {
        Set<String> keywords = keywordsOf(GrammarUtil.findRuleForName(GRAMMAR, "ElementKeyword"), new java.util.HashSet<>());
        assertTrue("ElementKeyword read from the grammar: " + keywords, keywords.size() > 40);
        assertSame("element keywords", keywords, new TreeSet<>(NodeCatalogue.allTags()));
    }

    @Test
    public void tagsTheNodeRulesAssignAreTheCatalogueTags() {
        assertSame("tags assigned by node rules", assignedTags(), new TreeSet<>(NodeCatalogue.allTags()));
    }

    @Test
    public void everyEntryParsesIntoItsKindAndValidatesInItsVersions() throws Exception {
        List<String> failures = new ArrayList<>();
        int checked = 0;
        for (NodeModel node : NodeCatalogue.all()) {
            for (String tag : node.tags()) {
                for (int version : NodeCatalogue.BOTH) {
                    if (node.accepts(tag, version)) {
                        checked++;
                        check(node, tag, version, failures);
                    }
                }
            }
        }
        assertTrue("only " + checked + " entries checked", checked > 60);
        assertTrue(String.join("\n", failures), failures.isEmpty());
    }

    private static void check(NodeModel node, String tag, int version, List<String> failures) throws Exception {
        String text = "<root BTCPP_format=\"" + version + "\" main_tree_to_execute=\"Main\">\n"
                + "<BehaviorTree ID=\"Main\">\n" + example(node, tag, version) + "\n</BehaviorTree>\n"
                + "<BehaviorTree ID=\"Other\"><AlwaysSuccess/></BehaviorTree>\n</root>\n";
        XtextResource resource = BtFiles.parse(text, new File("catalogue_" + tag + "_v" + version + ".bt"));
        String where = tag + " (version " + version + ")";
        if (!resource.getErrors().isEmpty()) {
            failures.add(where + " does not parse: " + resource.getErrors().get(0).getMessage() + "\n" + text);
            return;
        }
        TreeNode parsed = BtFiles.model(resource).getTrees().get(0).getNodes().get(0);
        Class<? extends EObject> family = switch (node.kind()) {
        case CONTROL -> ControlNode.class;
        case DECORATOR -> DecoratorNode.class;
        case SUBTREE -> SubtreeNode.class;
        default -> LeafNode.class;
        };
        if (!tag.equals(parsed.getTag()) || !family.isInstance(parsed)) {
            failures.add(where + " parses as " + parsed.eClass().getName() + " with tag " + parsed.getTag()
                    + ", not as a " + family.getSimpleName());
        }
        List<Issue> errors = BtFiles.validate(resource).stream().filter(i -> i.getSeverity() == Severity.ERROR)
                .toList();
        if (!errors.isEmpty()) {
            failures.add(where + ", written with its required ports, has errors:\n" + BtFiles.describe(errors) + "\n"
                    + text);
        }
    }

    /** The element with its required ports and its fewest children. */
    private static String example(NodeModel node, String tag, int version) {
        StringBuilder element = new StringBuilder("<").append(tag);
        for (PortModel port : node.ports(version)) {
            if (port.required()) {
                element.append(' ').append(port.name()).append("=\"").append(sample(port)).append('"');
            }
        }
        int children = node.children().min();
        if (children == 0) {
            return element.append("/>").toString();
        }
        element.append('>');
        for (int i = 0; i < children; i++) {
            element.append("<AlwaysSuccess/>");
        }
        return element.append("</").append(tag).append('>').toString();
    }

    private static String sample(PortModel port) {
        switch (port.name()) {
        case BuiltinNodes.ID:
            return "Other";
        case BuiltinNodes.CODE:
        case BuiltinNodes.IF:
            return "true";
        default:
            break;
        }
        if (!port.values().isEmpty()) {
            return port.values().get(0);
        }
        return switch (port.type()) {
        case INT, UNSIGNED -> "1";
        case DOUBLE -> "1.5";
        case BOOL -> "true";
        case STATUS -> "SUCCESS";
        default -> port.name().startsWith(BuiltinNodes.CASE_PREFIX) ? port.name() : "{" + port.name() + "}";
        };
    }

    @Test
    public void versionTablesComeFromTheCatalogue() {
        assertEquals("SequenceWithMemory", NodeCatalogue.onlyIn(NodeCatalogue.V3).get("SequenceStar"));
        assertEquals("RetryUntilSuccessful", NodeCatalogue.onlyIn(NodeCatalogue.V3).get("RetryUntilSuccesful"));
        assertEquals("", NodeCatalogue.onlyIn(NodeCatalogue.V4).get("Script"));
        assertTrue(NodeCatalogue.isRename("SequenceStar", "SequenceWithMemory"));
        assertTrue(!NodeCatalogue.isRename("SubTreePlus", "SubTree"));
    }
}
