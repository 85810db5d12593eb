package org.miron.ide.server;

import java.util.List;

import org.eclipse.lsp4j.ExecuteCommandParams;
import org.eclipse.xtext.ide.server.ILanguageServerAccess;
import org.eclipse.xtext.ide.server.commands.IExecutableCommandService;
import org.eclipse.xtext.util.CancelIndicator;

/** workspace/executeCommand `miron.generate`: runs the generators for a .miron file. */
public class GenerateCommandService implements IExecutableCommandService {
    public static final String COMMAND = "miron.generate";

    @Override
    public List<String> initialize() {
        return List.of(COMMAND);
    }

    @Override
    public Object execute(ExecuteCommandParams params, ILanguageServerAccess access, CancelIndicator cancelIndicator) {
        return "not yet";
    }
}
