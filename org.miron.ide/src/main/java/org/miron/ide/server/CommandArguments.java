package org.miron.ide.server;

import com.google.gson.JsonElement;
import com.google.gson.JsonPrimitive;

/** Arguments of workspace/executeCommand, however they arrived (JSON from a client, or objects in process). */
final class CommandArguments {
    private CommandArguments() {
    }

    /** A string argument, or null for anything else. */
    static String text(Object argument) {
        if (argument instanceof JsonPrimitive primitive) {
            return primitive.getAsString();
        }
        if (argument instanceof JsonElement) {
            return null;
        }
        return argument == null ? null : argument.toString();
    }
}
