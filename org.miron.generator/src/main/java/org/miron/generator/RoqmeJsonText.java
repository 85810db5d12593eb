package org.miron.generator;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;

import com.fasterxml.jackson.core.JsonGenerator;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.core.util.DefaultPrettyPrinter;
import com.fasterxml.jackson.core.util.Separators;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.ObjectWriter;
import com.fasterxml.jackson.databind.node.ObjectNode;
import com.fasterxml.jackson.databind.util.RawValue;

/**
 * The runtime model's text: laid out as io.json ({@link IoJsonPrinter}), except that types and
 * expressions stay on one line each ({"op": "<", "left": {"ref": "x", ...}, ...}), so that a
 * declaration reads in a few lines and a changed pattern diffs as one line.
 */
final class RoqmeJsonText {
    /** Fields whose object value is written on one line. */
    private static final Set<String> ONE_LINE = Set.of("type", "derived", "default", "init", "pattern", "expr", "value");

    private static final ObjectMapper MAPPER = new ObjectMapper().enable(JsonGenerator.Feature.WRITE_BIGDECIMAL_AS_PLAIN);
    private static final ObjectWriter ONE_LINE_WRITER = MAPPER.writer(oneLine());

    private RoqmeJsonText() {
    }

    static String print(ObjectNode root) {
        ObjectNode copy = root.deepCopy();
        try {
            inline(copy);
            return IoJsonPrinter.print(copy);
        } catch (JsonProcessingException e) {
            throw new IllegalStateException("a JSON tree always serializes", e);
        }
    }

    /** Replaces the object values of ONE_LINE fields (anywhere in node) by their one-line text. */
    private static void inline(JsonNode node) throws JsonProcessingException {
        if (node instanceof ObjectNode object) {
            List<Map.Entry<String, JsonNode>> fields = new ArrayList<>();
            object.fields().forEachRemaining(fields::add);
            for (Map.Entry<String, JsonNode> field : fields) {
                if (ONE_LINE.contains(field.getKey()) && field.getValue().isObject()) {
                    object.putRawValue(field.getKey(), new RawValue(ONE_LINE_WRITER.writeValueAsString(field.getValue())));
                } else {
                    inline(field.getValue());
                }
            }
        } else if (node != null && node.isArray()) {
            for (JsonNode element : node) {
                inline(element);
            }
        }
    }

    /** `{"a": 1, "b": [1, 2]}`: JSON's usual spacing, no line breaks. */
    private static DefaultPrettyPrinter oneLine() {
        Separators separators = Separators.createDefaultInstance()
                .withObjectFieldValueSpacing(Separators.Spacing.AFTER)
                .withObjectEntrySpacing(Separators.Spacing.AFTER)
                .withArrayValueSpacing(Separators.Spacing.AFTER)
                .withObjectEmptySeparator("")
                .withArrayEmptySeparator("");
        DefaultPrettyPrinter printer = new DefaultPrettyPrinter(separators);
        printer.indentObjectsWith(DefaultPrettyPrinter.NopIndenter.instance);
        printer.indentArraysWith(DefaultPrettyPrinter.NopIndenter.instance);
        return printer;
    }
}
