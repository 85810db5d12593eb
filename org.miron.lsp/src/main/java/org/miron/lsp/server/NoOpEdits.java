package org.miron.lsp.server;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Function;
import java.util.function.Predicate;

import org.eclipse.lsp4j.TextEdit;
import org.eclipse.lsp4j.WorkspaceEdit;
import org.eclipse.xtext.ide.server.Document;

/**
 * Drops the edits of a workspace edit that write what is already there. Xtext's rename re-serializes
 * every reference to the renamed element, including ones whose text does not change (a SubTree's
 * {@code ID="GoTo"} when a tree is renamed from elsewhere): editors count and show those as changes.
 */
final class NoOpEdits {

    private NoOpEdits() {
    }

    /** The edit without its no-op text edits; documents that the function cannot give are kept as they are. */
    static WorkspaceEdit drop(WorkspaceEdit edit, Function<String, Document> documents) {
        if (edit == null) {
            return null;
        }
        if (edit.getChanges() != null) {
            Map<String, List<TextEdit>> changes = new LinkedHashMap<>();
            edit.getChanges().forEach((uri, edits) -> {
                List<TextEdit> kept = edits.stream().filter(changes(documents.apply(uri))).toList();
                if (!kept.isEmpty()) {
                    changes.put(uri, kept);
                }
            });
            edit.setChanges(changes);
        }
        if (edit.getDocumentChanges() != null) {
            edit.getDocumentChanges().forEach(change -> {
                if (change.isLeft()) {
                    Document document = documents.apply(change.getLeft().getTextDocument().getUri());
                    Predicate<TextEdit> changes = changes(document);
                    change.getLeft().setEdits(change.getLeft().getEdits().stream()
                            .filter(e -> e.isRight() || changes.test(e.getLeft())).toList());
                }
            });
            edit.getDocumentChanges().removeIf(change -> change.isLeft() && change.getLeft().getEdits().isEmpty());
        }
        return edit;
    }

    private static Predicate<TextEdit> changes(Document document) {
        return edit -> {
            if (document == null) {
                return true;
            }
            try {
                int start = document.getOffSet(edit.getRange().getStart());
                int end = document.getOffSet(edit.getRange().getEnd());
                return !document.getContents().substring(start, end).equals(edit.getNewText());
            } catch (RuntimeException outside) {
                return true;
            }
        };
    }
}
