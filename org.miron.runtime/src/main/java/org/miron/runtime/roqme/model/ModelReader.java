package org.miron.runtime.roqme.model;

import com.fasterxml.jackson.core.JsonProcessingException;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import org.miron.runtime.Json;

/** Reads {@code name.roqme.json}; {@link org.miron.runtime.roqme.expr.Compiler} checks the references. */
public final class ModelReader {
    private ModelReader() {
    }

    public static RoqmeModel read(Path file) throws ModelException {
        String text;
        try {
            text = Files.readString(file);
        } catch (NoSuchFileException e) {
            throw new ModelException(file.toString(), "roqme-io", "no such file");
        } catch (IOException e) {
            throw new ModelException(file.toString(), "roqme-io", "cannot read: " + e.getMessage());
        }
        return parse(file.toString(), text);
    }

    public static RoqmeModel parse(String name, String text) throws ModelException {
        RoqmeModel m;
        try {
            m = Json.MAPPER.readValue(text, RoqmeModel.class);
        } catch (JsonProcessingException e) {
            var loc = e.getLocation();
            String at = loc == null ? name : name + ":" + loc.getLineNr() + ":" + loc.getColumnNr();
            throw new ModelException(at, "roqme-json", e.getOriginalMessage());
        }
        if (m == null) {
            throw new ModelException(name, "roqme-json", "empty file");
        }
        if (m.format() != 1) {
            throw new ModelException(name, "roqme-format", "unsupported format " + m.format() + " (this provider reads format 1)");
        }
        return m;
    }
}
