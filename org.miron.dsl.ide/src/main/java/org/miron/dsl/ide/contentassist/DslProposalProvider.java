package org.miron.dsl.ide.contentassist;

import org.eclipse.xtext.Assignment;
import org.eclipse.xtext.GrammarUtil;
import org.eclipse.xtext.Keyword;
import org.eclipse.xtext.ParserRule;
import org.eclipse.xtext.RuleCall;
import org.eclipse.xtext.ide.editor.contentassist.ContentAssistContext;
import org.eclipse.xtext.ide.editor.contentassist.ContentAssistEntry;
import org.eclipse.xtext.ide.editor.contentassist.IIdeContentProposalAcceptor;
import org.eclipse.xtext.ide.editor.contentassist.IdeContentProposalProvider;

/**
 * RoQME and MIRoN completion: Xtext's proposals plus the words of keyword-only datatype rules
 * that are assigned, such as {@code function=FunctionName} (avg, count, ...), which Xtext
 * proposes only as a placeholder.
 */
public class DslProposalProvider extends IdeContentProposalProvider {

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

    /** A rule like FunctionName: 'avg' | 'min' | ... (no names, numbers or other rules). */
    private static boolean onlyKeywords(ParserRule rule) {
        return !GrammarUtil.containedRuleCalls(rule).iterator().hasNext();
    }

}
