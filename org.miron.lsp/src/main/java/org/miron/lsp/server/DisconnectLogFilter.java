package org.miron.lsp.server;

import java.io.IOException;
import java.util.logging.Filter;
import java.util.logging.Handler;
import java.util.logging.LogRecord;
import java.util.logging.Logger;

/**
 * Keeps a client's disconnect out of the log. LSP4J logs every message it can no longer write
 * to a closed connection (diagnostics still being published, answers to requests in flight) as
 * SEVERE with the whole stack trace: about a hundred lines of "Broken pipe" per disconnect. A
 * disconnect is normal; the server logs it in one line where the connection ends.
 */
final class DisconnectLogFilter implements Filter {
    private static boolean installed;

    private DisconnectLogFilter() {
    }

    /**
     * Installs the filter on the handlers of the root logger (once): LSP4J's loggers hand their
     * records to those, and a parent logger's own filter would not see them.
     */
    static synchronized void install() {
        if (installed) {
            return;
        }
        installed = true;
        DisconnectLogFilter disconnects = new DisconnectLogFilter();
        for (Handler handler : Logger.getLogger("").getHandlers()) {
            Filter previous = handler.getFilter();
            handler.setFilter(record -> disconnects.isLoggable(record) && (previous == null || previous.isLoggable(record)));
        }
    }

    @Override
    public boolean isLoggable(LogRecord record) {
        return !isDisconnect(record.getThrown());
    }

    /** Whether a failure is the connection's end: an I/O error somewhere in its causes. */
    static boolean isDisconnect(Throwable thrown) {
        for (Throwable cause = thrown; cause != null; cause = cause.getCause()) {
            if (cause instanceof IOException) {
                return true;
            }
            if (cause.getCause() == cause) {
                break;
            }
        }
        return false;
    }
}
