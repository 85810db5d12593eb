package org.miron.bt.ide.server;

import java.lang.System.Logger.Level;
import java.util.List;

import org.eclipse.lsp4j.FormattingOptions;
import org.eclipse.lsp4j.TextEdit;
import org.eclipse.xtext.ide.server.Document;
import org.eclipse.xtext.ide.server.formatting.FormattingService;
import org.eclipse.xtext.resource.XtextResource;

/**
 * Formatting as `miron format` does it: a file with syntax errors is left as it is (no edits, and
 * the log says why). Xtext's formatters work on the node model of a complete parse; on a broken
 * one they fail ("No ITextReplacer configured") or would move text the user is still typing.
 */
public class SyntaxSafeFormattingService extends FormattingService {
    private static final System.Logger LOG = System.getLogger(SyntaxSafeFormattingService.class.getName());

    @Override
    public List<TextEdit> format(XtextResource resource, Document document, int offset, int length,
            FormattingOptions options) {
        if (resource.getParseResult() == null || resource.getParseResult().hasSyntaxErrors()) {
            LOG.log(Level.INFO, "not formatting {0}: it has syntax errors", resource.getURI());
            return List.of();
        }
        return super.format(resource, document, offset, length, options);
    }
}
