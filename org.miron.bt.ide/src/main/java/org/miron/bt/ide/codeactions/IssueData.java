package org.miron.bt.ide.codeactions;

import java.util.ArrayList;
import java.util.List;

import com.google.gson.JsonArray;
import com.google.gson.JsonElement;

/** The issue data of an LSP diagnostic as strings, however it arrived (JSON from a client, or an array in process). */
final class IssueData {

    private IssueData() {
    }

    static List<String> of(Object data) {
        List<String> result = new ArrayList<>();
        if (data instanceof JsonArray array) {
            for (JsonElement element : array) {
                if (element.isJsonPrimitive()) {
                    result.add(element.getAsString());
                }
            }
        } else if (data instanceof String[] array) {
            result.addAll(List.of(array));
        } else if (data instanceof List<?> list) {
            list.forEach(element -> result.add(String.valueOf(element)));
        } else if (data instanceof String text) {
            result.add(text);
        }
        result.removeIf(String::isEmpty);
        return result;
    }
}
