package org.miron.bt.validation;

import java.util.List;
import java.util.Set;
import java.util.regex.Pattern;
import java.util.stream.Collectors;

import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.xtext.nodemodel.ICompositeNode;
import org.eclipse.xtext.nodemodel.util.NodeModelUtils;
import org.eclipse.xtext.resource.XtextResource;
import org.eclipse.xtext.util.CancelIndicator;
import org.eclipse.xtext.validation.CheckMode;
import org.eclipse.xtext.validation.Issue;
import org.eclipse.xtext.validation.ResourceValidatorImpl;

/**
 * Leaves out the errors a syntax error causes (issue 23, item 8). After a missing or wrong close
 * tag the parser's recovery drops or misplaces what follows, so the validator and the linker judge
 * a model the file does not hold: "unknown SubTree ID" for a tree that is written but was not
 * parsed, a bogus missing include, a control "without children". So, while the file has syntax
 * errors, it reports them (only the first when it is about a close tag) and, of the rest, only what
 * lies before the first one and outside the elements around it; an unknown SubTree ID is left out
 * also there when a {@code <BehaviorTree ID="...">} of the text defines it.
 * Once the syntax is fixed, everything is checked again.
 */
public class BtResourceValidator extends ResourceValidatorImpl {

    private static final Set<String> CLOSE_TAGS = Set.of(BtIssueCodes.UNCLOSED_ELEMENT,
            BtIssueCodes.CLOSE_TAG_MISMATCH);

    private static final Set<String> UNRESOLVED = Set.of(BtIssueCodes.UNKNOWN_SUBTREE, BtIssueCodes.MISSING_INCLUDE,
            BtIssueCodes.UNKNOWN_REFERENCE);

    @Override
    public List<Issue> validate(Resource resource, CheckMode mode, CancelIndicator cancel) {
        List<Issue> issues = super.validate(resource, mode, cancel);
        int first = issues.stream().filter(Issue::isSyntaxError).mapToInt(BtResourceValidator::offset)
                .filter(offset -> offset >= 0).min().orElse(-1);
        if (first < 0) {
            return issues;
        }
        Issue firstIssue = issues.stream().filter(i -> i.isSyntaxError() && offset(i) == first).findFirst().get();
        // After a close tag missing or misspelt, the parser has closed the wrong elements: its
        // further syntax errors are about that, not about the file.
        boolean closeTag = CLOSE_TAGS.contains(firstIssue.getCode());
        String text = text(resource);
        return issues.stream().filter(issue -> issue.isSyntaxError() ? !closeTag || issue == firstIssue
                : !followsFrom(resource, issue, first, text)).collect(Collectors.toList());
    }

    private static boolean followsFrom(Resource resource, Issue issue, int firstSyntaxError, String text) {
        int offset = offset(issue);
        int length = issue.getLength() == null ? 0 : issue.getLength();
        if (offset < 0 || offset + length > firstSyntaxError || contains(resource, issue, firstSyntaxError, text)) {
            return true; // after the error, or on an element around it
        }
        return UNRESOLVED.contains(issue.getCode()) && definedInText(text, linkText(text, offset, length));
    }

    private static boolean definedInText(String text, String id) {
        if (text == null || id == null || id.isEmpty()) {
            return false;
        }
        return Pattern.compile("<BehaviorTree\\b[^>]*?\\bID\\s*=\\s*([\"'])" + Pattern.quote(id) + "\\1")
                .matcher(text).find();
    }

    /** The reference as written, without its quotes. */
    private static String linkText(String text, int offset, int length) {
        if (text == null || offset + length > text.length()) {
            return null;
        }
        String written = text.substring(offset, offset + length);
        return written.length() >= 2 && (written.charAt(0) == '"' || written.charAt(0) == '\'')
                ? written.substring(1, written.length() - 1)
                : written;
    }

    /** Whether the issue's element holds the offset, or ends where it is (its close tag's name). */
    private static boolean contains(Resource resource, Issue issue, int offset, String text) {
        if (issue.getUriToProblem() == null || issue.getUriToProblem().fragment() == null) {
            return false;
        }
        EObject element = resource.getEObject(issue.getUriToProblem().fragment());
        ICompositeNode node = element == null ? null : NodeModelUtils.getNode(element);
        if (node == null || node.getOffset() > offset) {
            return false;
        }
        if (offset < node.getEndOffset()) {
            return true;
        }
        // The parser ended the element at the wrong close tag: only "</" and blanks lie between.
        String between = text == null || offset > text.length() ? null : text.substring(node.getEndOffset(), offset).strip();
        return "".equals(between) || "</".equals(between);
    }

    private static int offset(Issue issue) {
        return issue.getOffset() == null ? -1 : issue.getOffset();
    }

    private static String text(Resource resource) {
        if (!(resource instanceof XtextResource xtext) || xtext.getParseResult() == null) {
            return null;
        }
        ICompositeNode root = xtext.getParseResult().getRootNode();
        return root == null ? null : root.getText();
    }
}
