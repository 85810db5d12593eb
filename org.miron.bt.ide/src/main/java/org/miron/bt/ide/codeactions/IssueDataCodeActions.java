package org.miron.bt.ide.codeactions;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.eclipse.lsp4j.CodeAction;
import org.eclipse.lsp4j.CodeActionKind;
import org.eclipse.lsp4j.Command;
import org.eclipse.lsp4j.Diagnostic;
import org.eclipse.lsp4j.Position;
import org.eclipse.lsp4j.Range;
import org.eclipse.lsp4j.TextEdit;
import org.eclipse.lsp4j.WorkspaceEdit;
import org.eclipse.lsp4j.jsonrpc.messages.Either;
import org.eclipse.xtext.ide.server.Document;
import org.eclipse.xtext.ide.server.codeActions.ICodeActionService2;
import org.miron.bt.bt.BTModel;
import org.miron.bt.nodes.NodeCatalogue;

/**
 * Quick fixes of all three languages, made from a diagnostic's issue code and issue data (see
 * docs/issue-codes.md): the validators already computed the replacement, the names to suggest or
 * the import to add, so a fix only turns them into text edits.
 */
public class IssueDataCodeActions implements ICodeActionService2 {

    /** The language server's command that converts a behaviour tree (org.miron.lsp's ConvertCommandService). */
    public static final String CONVERT_COMMAND = "miron.convert";

    private enum Fix {
        /** Rename an element's tag, also in its closing tag (data: the new tags, one action each). */
        RENAME_TAG,
        /** Replace the diagnostic's text with each name of the data (did you mean). */
        REPLACE,
        /** Add the import line data[0] to the file and write the reference as data[1]. */
        ADD_IMPORT,
        /** Add the include element data[0] after the root start tag. */
        ADD_INCLUDE,
        /** Close the element data[0] before the close tag the diagnostic is on. */
        CLOSE_ELEMENT
    }

    private static final Map<String, Fix> FIXES = Map.ofEntries(
            Map.entry("bt.retry-old-spelling", Fix.RENAME_TAG),
            Map.entry("bt.fallback-star", Fix.RENAME_TAG),
            Map.entry("bt.close-tag-mismatch", Fix.REPLACE),
            Map.entry("bt.unclosed-element", Fix.CLOSE_ELEMENT),
            Map.entry("bt.unknown-subtree", Fix.REPLACE),
            Map.entry("bt.unknown-main-tree", Fix.REPLACE),
            Map.entry("bt.unknown-reference", Fix.REPLACE),
            Map.entry("bt.missing-include", Fix.ADD_INCLUDE),
            Map.entry("bt.condition-typo", Fix.REPLACE),
            Map.entry("roqme.unknown-reference", Fix.REPLACE),
            Map.entry("miron.requirement-unknown-name", Fix.REPLACE),
            Map.entry("roqme.missing-import", Fix.ADD_IMPORT),
            // BehaviorTree.CPP 3/4 differences whose replacement is a rename (BtVersionValidator)
            Map.entry("bt.v3-only-element", Fix.RENAME_TAG),
            Map.entry("bt.v4-only-element", Fix.RENAME_TAG),
            Map.entry("bt.v3-only-attribute", Fix.REPLACE),
            Map.entry("bt.v4-only-attribute", Fix.REPLACE));

    /**
     * Replacements the issue data names but a rename would get wrong: in version 3 __autoremap
     * exists on SubTreePlus only. For elements the catalogue says which replacements are renames
     * (SubTreePlus → SubTree also changes how ports are remapped, BlackboardCheck → Precondition
     * takes other ports); the message tells what to write instead.
     */
    private static final Map<String, Set<String>> NOT_A_RENAME = Map.of(
            "bt.v4-only-attribute", Set.of("__autoremap"));

    /** The codes whose data is the other version's element, a rename only when the catalogue says so. */
    private static final Set<String> VERSION_ELEMENTS = Set.of("bt.v3-only-element", "bt.v4-only-element");

    @Override
    public List<Either<Command, CodeAction>> getCodeActions(Options options) {
        // Xtext passes neither document nor resource: read them as its own quick-fix service does.
        if (options.getDocument() == null && options.getLanguageServerAccess() != null) {
            return options.getLanguageServerAccess().doSyncRead(options.getURI(), context -> {
                options.setDocument(context.getDocument());
                options.setResource(context.getResource());
                return actions(options);
            });
        }
        return actions(options);
    }

    private List<Either<Command, CodeAction>> actions(Options options) {
        List<Either<Command, CodeAction>> actions = new ArrayList<>();
        convertAction(options, actions);
        Document document = options.getDocument();
        for (Diagnostic diagnostic : options.getCodeActionParams().getContext().getDiagnostics()) {
            Fix fix = diagnostic.getCode() == null || !diagnostic.getCode().isLeft() ? null
                    : FIXES.get(diagnostic.getCode().getLeft());
            List<String> data = IssueData.of(diagnostic.getData());
            if (fix != null) {
                data.removeAll(NOT_A_RENAME.getOrDefault(diagnostic.getCode().getLeft(), Set.of()));
                if (VERSION_ELEMENTS.contains(diagnostic.getCode().getLeft()) && document != null) {
                    String tag = text(document, diagnostic.getRange());
                    data.removeIf(instead -> !NodeCatalogue.isRename(tag, instead));
                }
            }
            if (fix == null || data.isEmpty() || document == null) {
                continue;
            }
            switch (fix) {
                case RENAME_TAG -> data.forEach(tag -> action(actions, options, diagnostic, "Change to " + tag,
                        TagRename.edits(options.getResource(), document, diagnostic.getRange(), tag)));
                case REPLACE -> data.forEach(name -> action(actions, options, diagnostic, "Change to " + name,
                        List.of(new TextEdit(diagnostic.getRange(), keepQuotes(document, diagnostic.getRange(), name)))));
                case ADD_IMPORT -> action(actions, options, diagnostic, "Add " + data.get(0),
                        addImport(document, diagnostic.getRange(), data));
                case ADD_INCLUDE -> action(actions, options, diagnostic, "Add " + data.get(0),
                        List.of(insertAfterRootTag(document, data.get(0))));
                case CLOSE_ELEMENT -> action(actions, options, diagnostic, "Add </" + data.get(0) + ">",
                        closeBefore(document, diagnostic.getRange(), data.get(0)));
            }
        }
        return actions;
    }

    /**
     * In a behaviour tree, a source action converting the file to the other BehaviorTree.CPP
     * version: the server's command miron.convert does it when chosen (nothing is computed here,
     * clients ask for code actions at every caret move).
     */
    private static void convertAction(Options options, List<Either<Command, CodeAction>> actions) {
        List<String> only = options.getCodeActionParams().getContext().getOnly();
        if (options.getResource() == null || options.getResource().getContents().isEmpty()
                || !(options.getResource().getContents().get(0) instanceof BTModel model)
                || only != null && only.stream().noneMatch(kind -> CodeActionKind.Source.startsWith(kind))) {
            return;
        }
        String target = model.formatVersion() == 4 ? "3" : "4";
        String title = "Convert to BehaviorTree.CPP " + target;
        CodeAction action = new CodeAction(title);
        action.setKind(CodeActionKind.Source);
        action.setCommand(new Command(title, CONVERT_COMMAND, List.of(options.getURI(), target)));
        actions.add(Either.forRight(action));
    }

    private static void action(List<Either<Command, CodeAction>> actions, Options options, Diagnostic diagnostic,
            String title, List<TextEdit> edits) {
        if (edits.isEmpty()) {
            return;
        }
        CodeAction action = new CodeAction(title);
        action.setKind(CodeActionKind.QuickFix);
        action.setDiagnostics(List.of(diagnostic));
        action.setEdit(new WorkspaceEdit(Map.of(options.getURI(), edits)));
        actions.add(Either.forRight(action));
    }

    /** A BT reference is a quoted attribute value: the quotes stay, the name inside changes. */
    private static String keepQuotes(Document document, Range range, String name) {
        String text = text(document, range);
        if (text.length() >= 2 && (text.charAt(0) == '"' || text.charAt(0) == '\'') && text.endsWith(text.substring(0, 1))) {
            return text.charAt(0) + name + text.charAt(0);
        }
        return name;
    }

    private static List<TextEdit> addImport(Document document, Range reference, List<String> data) {
        List<TextEdit> edits = new ArrayList<>();
        edits.add(new TextEdit(new Range(importLine(document), importLine(document)), data.get(0) + "\n"));
        if (data.size() > 1) {
            edits.add(new TextEdit(reference, data.get(1)));
        }
        return edits;
    }

    /** After the last import; else after the `roqme`/`miron` header line; else at the top. */
    private static Position importLine(Document document) {
        String[] lines = document.getContents().split("\n", -1);
        int after = -1;
        for (int i = 0; i < lines.length; i++) {
            String line = lines[i].strip();
            if (line.startsWith("import ")) {
                after = i;
            } else if (after < 0 && (line.startsWith("roqme ") || line.startsWith("miron ") || line.equals("roqme")
                    || line.equals("miron"))) {
                after = i;
            }
        }
        return new Position(after + 1, 0);
    }

    private static TextEdit insertAfterRootTag(Document document, String include) {
        String text = document.getContents();
        int root = text.indexOf("<root");
        int end = root < 0 ? -1 : text.indexOf('>', root);
        int offset = end < 0 ? 0 : end + 1;
        Position at = document.getPosition(offset);
        return new TextEdit(new Range(at, at), "\n  " + include);
    }

    /**
     * The diagnostic is on the name in the outer close tag ({@code </BehaviorTree>}): the missing
     * close tag goes just before it, on a line of its own one level deeper when the outer close tag
     * starts its line.
     */
    private static List<TextEdit> closeBefore(Document document, Range outerName, String tag) {
        String text = document.getContents();
        int close = text.lastIndexOf("</", document.getOffSet(outerName.getStart()));
        if (close < 0) {
            return List.of();
        }
        int lineStart = text.lastIndexOf('\n', close - 1) + 1;
        String indent = text.substring(lineStart, close);
        boolean ownLine = indent.isBlank();
        Position at = document.getPosition(ownLine ? lineStart : close);
        String closing = "</" + tag + ">";
        return List.of(new TextEdit(new Range(at, at), ownLine ? indent + (indent.contains("\t") ? "\t" : "  ") + closing + "\n" : closing));
    }

    private static String text(Document document, Range range) {
        int start = document.getOffSet(range.getStart());
        int end = document.getOffSet(range.getEnd());
        return document.getContents().substring(start, end);
    }
}
