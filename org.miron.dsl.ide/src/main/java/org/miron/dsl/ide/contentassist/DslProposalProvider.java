package org.miron.dsl.ide.contentassist;

import java.util.LinkedHashSet;
import java.util.Set;

import org.eclipse.emf.ecore.EClass;
import org.eclipse.emf.ecore.EClassifier;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EReference;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.eclipse.xtext.Assignment;
import org.eclipse.xtext.CrossReference;
import org.eclipse.xtext.EcoreUtil2;
import org.eclipse.xtext.GrammarUtil;
import org.eclipse.xtext.Keyword;
import org.eclipse.xtext.ParserRule;
import org.eclipse.xtext.RuleCall;
import org.eclipse.xtext.ide.editor.contentassist.ContentAssistContext;
import org.eclipse.xtext.ide.editor.contentassist.ContentAssistEntry;
import org.eclipse.xtext.ide.editor.contentassist.IIdeContentProposalAcceptor;
import org.eclipse.xtext.ide.editor.contentassist.IdeContentProposalProvider;
import org.eclipse.xtext.resource.IEObjectDescription;
import org.eclipse.xtext.xtext.CurrentTypeFinder;
import org.miron.dsl.miron.Import;

import com.google.inject.Inject;

/**
 * RoQME and MIRoN completion: Xtext's proposals plus the words of keyword-only datatype rules
 * that are assigned, such as {@code function=FunctionName} (avg, count, ...), which Xtext
 * proposes only as a placeholder, and MIRoN's import aliases.
 */
public class DslProposalProvider extends IdeContentProposalProvider {
    @Inject
    private CurrentTypeFinder currentTypeFinder;

    @Override
    protected void _createProposals(Assignment assignment, ContentAssistContext context,
            IIdeContentProposalAcceptor acceptor) {
        if (assignment.getTerminal() instanceof RuleCall call && call.getRule() instanceof ParserRule rule
                && GrammarUtil.isDatatypeRule(rule) && onlyKeywords(rule)) {
            for (Keyword keyword : GrammarUtil.containedKeywords(rule)) {
                ContentAssistEntry entry = getProposalCreator().createProposal(keyword.getValue(), context,
                        ContentAssistEntry.KIND_FUNCTION, null);
                if (entry != null) {
                    entry.setDescription(rule.getName());
                    acceptor.accept(entry, getProposalPriorities().getKeywordPriority(keyword.getValue(), entry));
                }
            }
            return;
        }
        super._createProposals(assignment, context, acceptor);
    }

    /**
     * Besides the qualified names, the import aliases they start with ({@code main}, {@code roqme}),
     * for the references where the alias leads to something of the expected kind.
     */
    @Override
    protected void _createProposals(CrossReference reference, ContentAssistContext context,
            IIdeContentProposalAcceptor acceptor) {
        super._createProposals(reference, context, acceptor);
        EObject model = context.getCurrentModel();
        EClassifier type = currentTypeFinder.findCurrentTypeAfter(reference);
        EReference eReference = type instanceof EClass eClass ? GrammarUtil.getReference(reference, eClass) : null;
        if (model == null || eReference == null) {
            return;
        }
        Set<String> aliases = new LinkedHashSet<>();
        for (Import anImport : EcoreUtil2.getAllContentsOfType(EcoreUtil.getRootContainer(model), Import.class)) {
            if (anImport.getAlias() != null) {
                aliases.add(anImport.getAlias());
            }
        }
        Set<String> reachable = new LinkedHashSet<>();
        for (IEObjectDescription candidate : getScopeProvider().getScope(model, eReference).getAllElements()) {
            if (candidate.getName().getSegmentCount() > 1 && aliases.contains(candidate.getName().getFirstSegment())) {
                reachable.add(candidate.getName().getFirstSegment());
            }
        }
        for (String alias : reachable) {
            ContentAssistEntry entry = getProposalCreator().createProposal(alias, context, ContentAssistEntry.KIND_MODULE,
                    null);
            if (entry != null) {
                entry.setDescription("import alias");
                acceptor.accept(entry, getProposalPriorities().getDefaultPriority(entry));
            }
        }
    }

    /**
     * Right after "::" or "." only a name can follow (issue 23, item 6): the parser's follow set there
     * also held operators ("&", "'", "->", ...) of the expression before.
     */
    @Override
    protected boolean filterKeyword(Keyword keyword, ContentAssistContext context) {
        if (!super.filterKeyword(keyword, context)) {
            return false;
        }
        if (Character.isLetter(keyword.getValue().charAt(0)) || context.getRootNode() == null) {
            return true;
        }
        String text = context.getRootNode().getText();
        int end = Math.min(context.getOffset() - context.getPrefix().length(), text.length());
        String before = text.substring(0, Math.max(0, end));
        return !before.endsWith("::") && !before.endsWith(".");
    }

    /** A rule like FunctionName: 'avg' | 'min' | ... (no names, numbers or other rules). */
    private static boolean onlyKeywords(ParserRule rule) {
        return !GrammarUtil.containedRuleCalls(rule).iterator().hasNext();
    }

}
