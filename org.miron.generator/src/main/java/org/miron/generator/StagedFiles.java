package org.miron.generator;

import java.util.ArrayList;
import java.util.List;

import org.eclipse.xtext.generator.IFileSystemAccess2;
import org.eclipse.xtext.generator.InMemoryFileSystemAccess;

/**
 * Generated files held in memory until the whole model has generated, then flushed to the real
 * file-system access: a model with errors leaves no partial output. Files keep the order they
 * were generated in (the in-memory access sorts them by name).
 */
public class StagedFiles extends InMemoryFileSystemAccess {
    private final List<String> order = new ArrayList<>();

    @Override
    public void generateFile(String fileName, String outputConfigName, CharSequence contents) {
        super.generateFile(fileName, outputConfigName, contents);
        if (!order.contains(fileName)) {
            order.add(fileName);
        }
    }

    /** The file names (relative to the output folder), in generation order. */
    public List<String> names() {
        return List.copyOf(order);
    }

    /** The text of a generated file, or null. */
    public String text(String fileName) {
        CharSequence text = getTextFiles().get(getFileName(fileName, DEFAULT_OUTPUT));
        return text == null ? null : text.toString();
    }

    /** Writes every file to target, in generation order. */
    public void flushTo(IFileSystemAccess2 target) {
        for (String name : order) {
            target.generateFile(name, text(name));
        }
    }
}
