package org.miron.lsp.server;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import org.eclipse.lsp4j.ExecuteCommandParams;
import org.eclipse.xtext.ide.server.ILanguageServerAccess;
import org.eclipse.xtext.ide.server.commands.IExecutableCommandService;
import org.eclipse.xtext.resource.XtextResource;
import org.eclipse.xtext.util.CancelIndicator;
import org.eclipse.xtext.validation.CheckMode;
import org.eclipse.xtext.validation.Issue;

/**
 * workspace/executeCommand {@code miron.generate} with arguments {@code [uri]} or
 * {@code [uri, outputFolder]}: runs the generators on the .miron file as the editor has it
 * (unsaved changes included) and writes the woven tree, the MiniZinc files and the io.json into the
 * output folder (default: {@code generated/} next to the model). Answers a JSON object: `ok`,
 * `message`, the files `written` and the `errors` ("file:line:col: message").
 */
public class GenerateCommandService implements IExecutableCommandService {
    public static final String COMMAND = "miron.generate";

    @Override
    public List<String> initialize() {
        return List.of(COMMAND);
    }

    @Override
    public Object execute(ExecuteCommandParams params, ILanguageServerAccess access, CancelIndicator cancelIndicator) {
        CommandArguments arguments = new CommandArguments(params);
        String uri = arguments.text(0);
        Map<String, Object> result;
        if (uri == null || !(uri.endsWith(".miron") || uri.endsWith(".roqme"))) {
            result = answer(List.of(), List.of(), "miron.generate needs the URI of a .miron or .roqme file as first argument");
        } else {
            String output = arguments.text(1);
            try {
                result = access.doSyncRead(uri, context -> generate((XtextResource) context.getResource(), output,
                        cancelIndicator));
            } catch (RuntimeException unreadable) {
                // A URI outside the workspace, or a file gone: an answer, not an internal error.
                result = answer(List.of(), List.of(), "miron.generate: cannot read " + uri + ": " + unreadable);
            }
        }
        CommandArguments.tell(access, result);
        return result;
    }

    private static Map<String, Object> generate(XtextResource resource, String output, CancelIndicator cancel) {
        if (resource == null || resource.getURI() == null || !resource.getURI().isFile()) {
            return answer(List.of(), List.of(), "miron.generate: the model is not a file of this workspace");
        }
        Path model = Path.of(resource.getURI().toFileString());
        Path folder = output == null ? model.resolveSibling("generated") : model.resolveSibling(output);
        List<String> errors = new ArrayList<>();
        for (Issue issue : resource.getResourceServiceProvider().getResourceValidator().validate(resource,
                CheckMode.ALL, cancel)) {
            if (issue.getSeverity() == org.eclipse.xtext.diagnostics.Severity.ERROR) {
                errors.add(model.getFileName() + ":" + issue.getLineNumber() + ":" + issue.getColumn() + ": "
                        + issue.getMessage());
            }
        }
        if (!errors.isEmpty()) {
            return answer(List.of(), errors, "Not generated: " + model.getFileName() + " has " + errors.size()
                    + (errors.size() == 1 ? " error" : " errors") + ", first: " + errors.get(0));
        }
        ModelGeneration.Result generated = ModelGeneration.run(resource, folder);
        if (!generated.errors().isEmpty()) {
            return answer(List.of(), generated.errors(), "Not generated: " + generated.errors().get(0));
        }
        int count = generated.written().size();
        return answer(generated.written(), List.of(), "Generated " + count + (count == 1 ? " file" : " files") + " into "
                + folder + ": " + String.join(", ", generated.written().stream()
                        .map(p -> Path.of(p).getFileName().toString()).toList()));
    }

    private static Map<String, Object> answer(List<String> written, List<String> errors, String message) {
        Map<String, Object> result = new LinkedHashMap<>();
        result.put("ok", errors.isEmpty() && !written.isEmpty());
        result.put("message", message);
        result.put("written", written);
        result.put("errors", errors);
        return result;
    }

}
