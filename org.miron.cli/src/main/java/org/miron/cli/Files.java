package org.miron.cli;

import org.miron.generator.standalone.ModelLoader;
import java.io.File;
import java.io.PrintWriter;
import java.util.List;

import picocli.CommandLine.Model.CommandSpec;

/** Command-line argument checks shared by the commands that read model files. */
final class Files {
    static final int USAGE = 2;

    private Files() {
    }

    /** Null when every file can be read and has a supported type, else the usage exit code. */
    static Integer checkReadable(List<File> files, CommandSpec spec) {
        PrintWriter err = spec.commandLine().getErr();
        for (File file : files) {
            if (!file.isFile() || !file.canRead()) {
                err.println(file + ": error: no such file");
                err.flush();
                return USAGE;
            }
            if (!ModelLoader.supports(file.getName())) {
                err.println(file + ": error: unsupported file type, expected " + ModelLoader.supportedExtensions());
                err.flush();
                return USAGE;
            }
        }
        return null;
    }
}
