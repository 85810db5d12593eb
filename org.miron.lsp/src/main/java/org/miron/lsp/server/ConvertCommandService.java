package org.miron.lsp.server;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import org.eclipse.emf.common.util.URI;
import org.eclipse.lsp4j.ApplyWorkspaceEditParams;
import org.eclipse.lsp4j.ExecuteCommandParams;
import org.eclipse.lsp4j.Position;
import org.eclipse.lsp4j.Range;
import org.eclipse.lsp4j.TextEdit;
import org.eclipse.lsp4j.WorkspaceEdit;
import org.eclipse.xtext.ide.server.Document;
import org.eclipse.xtext.ide.server.ILanguageServerAccess;
import org.eclipse.xtext.ide.server.commands.IExecutableCommandService;
import org.eclipse.xtext.resource.XtextResource;
import org.eclipse.xtext.resource.XtextResourceSet;
import org.eclipse.xtext.util.CancelIndicator;
import org.miron.bt.bt.BTModel;
import org.miron.bt.formats.BtFormatConverter;
import org.miron.bt.formats.ConversionProblem;

/**
 * workspace/executeCommand {@code miron.convert} with arguments {@code [uri, version]}: converts
 * the behaviour tree as the editor has it to BehaviorTree.CPP 3 or 4 (what `miron convert` does,
 * comments and layout kept) and asks the client to apply the edit (workspace/applyEdit), so that
 * it can be undone there. Answers a JSON object: `ok`, `message` and the `errors` of elements
 * without an equivalent ("file:line:col: error [code]: message").
 */
public class ConvertCommandService implements IExecutableCommandService {
    public static final String COMMAND = "miron.convert";

    @Override
    public List<String> initialize() {
        return List.of(COMMAND);
    }

    @Override
    public Object execute(ExecuteCommandParams params, ILanguageServerAccess access, CancelIndicator cancelIndicator) {
        CommandArguments arguments = new CommandArguments(params);
        String uri = arguments.text(0);
        String version = arguments.text(1);
        Map<String, Object> result;
        if (uri == null || !("3".equals(version) || "4".equals(version))) {
            result = answer(false, List.of(), "miron.convert needs the URI of a behaviour tree and the version, 3 or 4");
        } else {
            try {
                result = access.doSyncRead(uri, context -> convert((XtextResource) context.getResource(),
                        context.getDocument(), uri, Integer.parseInt(version), access));
            } catch (RuntimeException unreadable) {
                result = answer(false, List.of(), "miron.convert: cannot read " + uri + ": " + unreadable);
            }
        }
        CommandArguments.tell(access, result);
        return result;
    }

    /** Converts a copy parsed from the editor's text: the workspace's own model stays as it is. */
    private static Map<String, Object> convert(XtextResource live, Document document, String uri, int version,
            ILanguageServerAccess access) {
        if (live == null || live.getContents().isEmpty() || !(live.getContents().get(0) instanceof BTModel)) {
            return answer(false, List.of(), "miron.convert: " + uri + " is not a behaviour tree");
        }
        XtextResourceSet set = live.getResourceServiceProvider().get(XtextResourceSet.class);
        XtextResource copy = (XtextResource) set.createResource(live.getURI());
        try {
            copy.load(new ByteArrayInputStream(document.getContents().getBytes(StandardCharsets.UTF_8)), null);
        } catch (IOException e) {
            return answer(false, List.of(), "miron.convert: " + e.getMessage());
        }
        if (copy.getParseResult() == null || copy.getParseResult().hasSyntaxErrors()) {
            return answer(false, List.of(), "Not converted: the file has syntax errors");
        }
        BtFormatConverter.ConvertedFile converted = BtFormatConverter.convertFile(copy, version);
        String name = URI.createURI(uri).lastSegment();
        if (!converted.conversion().succeeded()) {
            List<String> errors = new ArrayList<>();
            for (ConversionProblem problem : converted.conversion().getProblems()) {
                errors.add(problem.format(name));
            }
            return answer(false, errors, "Not converted to BehaviorTree.CPP " + version + ": " + errors.get(0));
        }
        if (converted.text().equals(document.getContents())) {
            return answer(true, List.of(), name + " is already BehaviorTree.CPP " + version);
        }
        Range all = new Range(new Position(0, 0), document.getPosition(document.getContents().length()));
        WorkspaceEdit edit = new WorkspaceEdit(Map.of(uri, List.of(new TextEdit(all, converted.text()))));
        if (access.getLanguageClient() == null) {
            return answer(false, List.of(), "miron.convert: no client to apply the edit");
        }
        // Not waited for: the client applies the edit on its own thread, which may need this server.
        access.getLanguageClient().applyEdit(new ApplyWorkspaceEditParams(edit, "Convert to BehaviorTree.CPP " + version));
        return answer(true, List.of(), "Converted " + name + " to BehaviorTree.CPP " + version);
    }

    private static Map<String, Object> answer(boolean ok, List<String> errors, String message) {
        Map<String, Object> result = new LinkedHashMap<>();
        result.put("ok", ok);
        result.put("message", message);
        result.put("errors", errors);
        return result;
    }
}
