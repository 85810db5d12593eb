package org.miron.runtime.engine;

import com.fasterxml.jackson.databind.JsonNode;
import java.io.BufferedWriter;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.logging.Logger;
import org.miron.runtime.Json;

/** Append-only JSON-lines log of every solve: inputs, outputs, backend, latency. */
public final class DecisionLog implements AutoCloseable {
    private static final Logger LOG = Logger.getLogger(DecisionLog.class.getName());
    private final Path path;
    private BufferedWriter out;
    private boolean warned;

    public DecisionLog(Path path) throws IOException {
        this.path = path;
        Path dir = path.toAbsolutePath().getParent();
        if (dir != null) {
            Files.createDirectories(dir);
        }
        this.out = Files.newBufferedWriter(path, StandardCharsets.UTF_8, StandardOpenOption.CREATE,
                StandardOpenOption.APPEND, StandardOpenOption.WRITE);
    }

    /** One line per entry, flushed so a crash loses nothing; a full disk is logged, not fatal. */
    public synchronized void append(JsonNode entry) {
        if (out == null) {
            return;
        }
        try {
            out.write(Json.write(entry));
            out.newLine();
            out.flush();
        } catch (IOException e) {
            if (!warned) {
                LOG.warning("cannot write decision log " + path + ": " + e.getMessage());
                warned = true;
            }
        }
    }

    @Override
    public synchronized void close() {
        if (out != null) {
            try {
                out.close();
            } catch (IOException ignored) {
                // closing anyway
            }
            out = null;
        }
    }
}
