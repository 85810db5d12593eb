package org.miron.lsp.diagram;

import org.eclipse.sprotty.ActionMessage;
import org.eclipse.sprotty.server.json.ActionTypeAdapter;

import com.google.gson.Gson;
import com.google.gson.GsonBuilder;
import com.google.gson.JsonElement;

/**
 * Sprotty's action messages to and from JSON with Sprotty's own adapters (an action's class by its
 * {@code kind}). LSP4J sees only the JSON trees, so its own Gson needs no Sprotty types.
 */
final class DiagramJson {
    private static final Gson GSON = ActionTypeAdapter.configureGson(new GsonBuilder()).create();

    private DiagramJson() {
    }

    /** The message, or null when it is not one (an unknown action kind, no action). */
    static ActionMessage read(JsonElement json) {
        try {
            ActionMessage message = GSON.fromJson(json, ActionMessage.class);
            return message == null || message.getAction() == null ? null : message;
        } catch (RuntimeException malformed) { // from a client: refused, never a crash
            return null;
        }
    }

    static JsonElement write(ActionMessage message) {
        return GSON.toJsonTree(message);
    }
}
