package org.miron.generator;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.util.ArrayDeque;
import java.util.Deque;

import com.fasterxml.jackson.core.JsonGenerator;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.core.JsonStreamContext;
import com.fasterxml.jackson.core.util.DefaultIndenter;
import com.fasterxml.jackson.core.util.DefaultPrettyPrinter;
import com.fasterxml.jackson.core.util.Separators;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

/**
 * Jackson's pretty printer with two-space indentation, '\n' on every platform and `"key": value`,
 * except that an array of values stays on one line ("values": [10, 11, 12]) while each object of
 * an array starts a line of its own: files stay short and regenerated ones diff entry by entry.
 */
final class IoJsonPrinter extends DefaultPrettyPrinter {
    private static final long serialVersionUID = 1L;
    private static final ObjectMapper MAPPER = new ObjectMapper().enable(JsonGenerator.Feature.WRITE_BIGDECIMAL_AS_PLAIN);

    /** Per open array: whether it holds objects (then its closing bracket goes on a new line). */
    private final Deque<Boolean> arrays = new ArrayDeque<>();

    IoJsonPrinter() {
        super(Separators.createDefaultInstance().withObjectFieldValueSpacing(Separators.Spacing.AFTER));
        indentObjectsWith(new DefaultIndenter("  ", "\n"));
    }

    /** A generated JSON file's text (io.json, requirements.json, roqme.json): the tree in this layout, numbers plain, a final newline. */
    static String print(JsonNode tree) {
        try {
            return MAPPER.writer(new IoJsonPrinter()).writeValueAsString(tree) + "\n";
        } catch (JsonProcessingException e) {
            throw new UncheckedIOException(e); // a tree of plain nodes always serializes
        }
    }

    private IoJsonPrinter(IoJsonPrinter base) {
        super(base);
    }

    @Override
    public DefaultPrettyPrinter createInstance() {
        return new IoJsonPrinter(this);
    }

    @Override
    public void writeStartArray(JsonGenerator g) throws IOException {
        arrays.push(false);
        g.writeRaw('[');
    }

    @Override
    public void beforeArrayValues(JsonGenerator g) {
        // An object's line break is written by writeStartObject; a value follows '[' directly.
    }

    @Override
    public void writeArrayValueSeparator(JsonGenerator g) throws IOException {
        g.writeRaw(arrays.peek() ? "," : ", ");
    }

    @Override
    public void writeStartObject(JsonGenerator g) throws IOException {
        // The generator has already entered the new object: its parent tells whether it is in an array.
        JsonStreamContext parent = g.getOutputContext().getParent();
        if (parent != null && parent.inArray()) {
            if (!arrays.peek()) {
                arrays.pop();
                arrays.push(true);
                _nesting++;
            }
            _objectIndenter.writeIndentation(g, _nesting);
        }
        super.writeStartObject(g);
    }

    @Override
    public void writeEndArray(JsonGenerator g, int nrOfValues) throws IOException {
        if (arrays.pop()) {
            _nesting--;
            _objectIndenter.writeIndentation(g, _nesting);
        }
        g.writeRaw(']');
    }
}
