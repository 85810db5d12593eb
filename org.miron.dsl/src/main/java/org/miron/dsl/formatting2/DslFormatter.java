package org.miron.dsl.formatting2;

import java.util.Set;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.xtext.formatting2.AbstractJavaFormatter;
import org.eclipse.xtext.AbstractRule;
import org.eclipse.xtext.formatting2.IFormattableDocument;
import org.eclipse.xtext.formatting2.ITextReplacer;
import org.eclipse.xtext.formatting2.ITextReplacerContext;
import org.eclipse.xtext.formatting2.internal.CommentReplacer;
import org.eclipse.xtext.formatting2.internal.WhitespaceReplacer;
import org.eclipse.xtext.formatting2.regionaccess.IComment;
import org.eclipse.xtext.formatting2.regionaccess.ISemanticRegion;
import org.miron.dsl.miron.ArchBinding;
import org.miron.dsl.miron.Binding;
import org.miron.dsl.miron.BehaviorTreeEnumType;
import org.miron.dsl.miron.ImpactOnQuality;
import org.miron.dsl.miron.NumericSampledType;
import org.miron.dsl.miron.Requirement;
import org.miron.dsl.miron.Rule;
import org.miron.dsl.roqme.BeliefExpression;
import org.miron.dsl.roqme.BoundedType;
import org.miron.dsl.roqme.FunctionCall;
import org.miron.dsl.roqme.Observation;
import org.miron.dsl.roqme.RangeExpression;
import org.miron.dsl.roqme.RepeatExpression;
import org.miron.dsl.roqme.RoqmeModel;
import org.miron.dsl.roqme.UnaryExpression;

/**
 * Formatter of RoQME and MIRoN files: one declaration per line (at most one blank line kept
 * between them), single spaces between tokens, none inside parentheses, before commas, in ranges
 * (0:1:100), calls avg(x), x'avg and impacts safety++; the blocks of observations, BT enums,
 * samples, arch bindings and rules get one item per indented line, while short lists such as
 * enum { A, B } and impact sets stay on one line. Comments are kept.
 */
public class DslFormatter extends AbstractJavaFormatter {

    /** Tokens with a spacing rule of their own, next to which a written line break is not kept. */
    private static final Set<String> GLUED = Set.of("(", ")", "[", "]", ",", "'", "@", "!", "-", ":", "+", "++", "+++",
            "--", "---");

    /** Elements whose { } block holds one item per line. */
    private static final Set<Class<?>> BLOCKS = Set.of(Observation.class, BehaviorTreeEnumType.class,
            NumericSampledType.class, ArchBinding.class, Rule.class);

    /**
     * Comments are the grammar's ML_COMMENT/SL_COMMENT; anything else in a hidden region (a stray
     * token of a half-written file, which rename's re-formatting of the changed region meets) is
     * kept as written: Xtext would fail with "No ITextReplacer configured for (null)".
     */
    @Override
    public ITextReplacer createCommentReplacer(IComment comment) {
        if (comment.getGrammarElement() instanceof AbstractRule) {
            return super.createCommentReplacer(comment);
        }
        return new CommentReplacer(comment) {
            @Override
            public void configureWhitespace(WhitespaceReplacer leading, WhitespaceReplacer trailing) {
            }

            @Override
            public ITextReplacerContext createReplacements(ITextReplacerContext context) {
                return context;
            }
        };
    }

    protected void format(RoqmeModel model, IFormattableDocument doc) {
        // defaults first, at low priority, so that every rule below overrides them
        for (ISemanticRegion region : allSemanticRegions(model)) {
            doc.append(region, f -> {
                f.oneSpace();
                f.lowPriority();
            });
        }
        for (EObject element : model.eContents()) {
            if (previousHiddenRegion(element).getPreviousSemanticRegion() != null) {
                doc.prepend(element, f -> f.setNewLines(1, 1, 2));
            }
        }
        ISemanticRegion last = null;
        for (ISemanticRegion region : allSemanticRegions(model)) {
            formatToken(region, doc);
            last = region;
        }
        if (last != null) {
            doc.append(last, f -> f.setNewLines(1)); // the file ends with one line break
        }
    }

    /** avg(, repeat(, range(, belief(: the parenthesis of a call, not of a sub-expression. */
    private static boolean isCall(ISemanticRegion paren) {
        ISemanticRegion previous = paren.getPreviousSemanticRegion();
        if (previous == null) {
            return false;
        }
        EObject owner = previous.getSemanticElement();
        String word = previous.getText();
        return owner instanceof FunctionCall && word.equals(((FunctionCall) owner).getFunction())
                || owner instanceof RepeatExpression && word.equals("repeat")
                || owner instanceof RangeExpression && word.equals("range")
                || owner instanceof BeliefExpression && word.equals("belief");
    }

    private void formatToken(ISemanticRegion region, IFormattableDocument doc) {
        String text = region.getText();
        EObject owner = region.getSemanticElement();
        // A block written on one line (`implies { a = x, b = y }`) stays on one line; an arch binding
        // always has one item per line.
        boolean block = BLOCKS.stream().anyMatch(c -> c.isInstance(owner))
                && (owner instanceof ArchBinding || writtenOnLines(owner));
        if (text.startsWith("/**")) {
            doc.append(region, this::newLine);
        } else if (text.equals(",")) {
            doc.prepend(region, this::noSpace);
            if (block) {
                doc.append(region, this::newLine);
            }
        } else if (text.equals("(") || text.equals("[")) {
            doc.append(region, this::noSpace);
            if (text.equals("(") && isCall(region)) {
                doc.prepend(region, this::noSpace);
            }
        } else if (text.equals(")") || text.equals("]")) {
            doc.prepend(region, this::noSpace);
        } else if (text.equals("'") || (text.equals(":") && owner instanceof BoundedType)) {
            doc.surround(region, this::noSpace);
        } else if (text.equals("@")) {
            doc.append(region, this::noSpace);
        } else if (owner instanceof ImpactOnQuality && text.matches("[-+]+")) {
            doc.prepend(region, this::noSpace);
        } else if (owner instanceof UnaryExpression && (text.equals("-") || text.equals("!"))) {
            doc.append(region, this::noSpace);
        } else if (text.equals("{") && block) {
            ISemanticRegion close = regionFor(owner).keyword("}");
            doc.append(region, this::newLine);
            if (close != null) {
                doc.prepend(close, this::newLine);
                doc.interior(region, close, this::indent);
            }
        } else if (owner instanceof ArchBinding && text.startsWith("parameter") || owner instanceof ArchBinding
                && text.equals("component")) {
            doc.prepend(region, this::newLine);
        } else if (owner instanceof Binding && region.getPreviousSemanticRegion() != null
                && region.getPreviousHiddenRegion().isMultiline() && isFirstOf(region, owner)) {
            // `}` then `in arch {` on a line of its own (a blank line between kept), as written.
            doc.prepend(region, f -> f.setNewLines(1, 1, 2));
        } else if (owner instanceof Rule rule && text.equals("implies")) {
            formatRule(rule, region, doc);
        } else if (owner instanceof Requirement requirement && text.equals(":")
                && region.getNextHiddenRegion().isMultiline()) {
            // a long formula written on the next line stays there, one level in (docs/requirements.md)
            ISemanticRegion last = lastRegion(requirement);
            doc.append(region, this::newLine);
            if (last != null) {
                doc.set(region.getNextHiddenRegion(), last.getNextHiddenRegion(), this::indent);
            }
        }
        // one action per line in an observation block
        if (owner instanceof Observation && text.equals("{") && block) {
            for (EObject action : ((Observation) owner).getActions()) {
                doc.prepend(action, this::newLine);
            }
        }
    }

    /**
     * A rule: {@code implies} on its own line, one level in; the line breaks written in the
     * condition kept, two levels in (as the examples write a long condition).
     */
    private void formatRule(Rule rule, ISemanticRegion implies, IFormattableDocument doc) {
        ISemanticRegion colon = regionFor(rule).keyword(":");
        ISemanticRegion last = lastRegion(rule);
        doc.prepend(implies, this::newLine);
        if (colon == null || last == null) {
            return;
        }
        doc.set(colon.getNextHiddenRegion(), last.getNextHiddenRegion(), this::indent);
        ISemanticRegion lastOfCondition = implies.getPreviousSemanticRegion();
        if (lastOfCondition != colon) {
            doc.set(colon.getNextHiddenRegion(), implies.getPreviousHiddenRegion(), this::indent);
            for (ISemanticRegion r = colon.getNextSemanticRegion(); r != null && r != lastOfCondition; r = r
                    .getNextSemanticRegion()) {
                // Only between tokens no other rule spaces (a break inside "( x" would conflict with it).
                if (r.getNextHiddenRegion().isMultiline() && !GLUED.contains(r.getText())
                        && !GLUED.contains(r.getNextSemanticRegion().getText())) {
                    doc.append(r, this::newLine);
                }
            }
        }
    }

    private ISemanticRegion lastRegion(EObject element) {
        ISemanticRegion last = null;
        for (ISemanticRegion region : allSemanticRegions(element)) {
            last = region;
        }
        return last;
    }

    private boolean isFirstOf(ISemanticRegion region, EObject element) {
        for (ISemanticRegion first : allSemanticRegions(element)) {
            return first == region;
        }
        return false;
    }

    /** Whether an element's { } block was written over several lines. */
    private boolean writtenOnLines(EObject owner) {
        ISemanticRegion open = regionFor(owner).keyword("{");
        ISemanticRegion close = regionFor(owner).keyword("}");
        if (open == null || close == null) {
            return true;
        }
        return getTextRegionAccess().textForOffset(open.getOffset(), close.getEndOffset() - open.getOffset())
                .indexOf('\n') >= 0;
    }
}
