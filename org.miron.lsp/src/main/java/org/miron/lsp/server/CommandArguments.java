package org.miron.lsp.server;

import java.util.List;
import java.util.Map;

import org.eclipse.lsp4j.ExecuteCommandParams;
import org.eclipse.lsp4j.MessageParams;
import org.eclipse.lsp4j.MessageType;
import org.eclipse.xtext.ide.server.ILanguageServerAccess;

import com.google.gson.JsonElement;
import com.google.gson.JsonPrimitive;

/**
 * The arguments of a workspace/executeCommand, however they arrived (JSON from a client, or
 * objects in process), and the answer's message shown to the user.
 */
final class CommandArguments {
    private final List<Object> arguments;

    CommandArguments(ExecuteCommandParams params) {
        arguments = params.getArguments() == null ? List.of() : params.getArguments();
    }

    /** Argument i as a string, or null when it is missing or not a string. */
    String text(int i) {
        if (i >= arguments.size()) {
            return null;
        }
        Object argument = arguments.get(i);
        if (argument instanceof JsonPrimitive primitive) {
            return primitive.getAsString();
        }
        if (argument instanceof JsonElement) {
            return null;
        }
        return argument == null ? null : argument.toString();
    }

    /** Shows the answer's `message` to the user, as information when `ok`, else as an error. */
    static void tell(ILanguageServerAccess access, Map<String, Object> answer) {
        if (access.getLanguageClient() != null) {
            access.getLanguageClient().showMessage(new MessageParams(
                    Boolean.TRUE.equals(answer.get("ok")) ? MessageType.Info : MessageType.Error,
                    (String) answer.get("message")));
        }
    }
}
