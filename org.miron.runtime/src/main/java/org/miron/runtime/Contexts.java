package org.miron.runtime;

import java.nio.channels.ClosedChannelException;
import java.util.logging.Level;
import java.util.logging.Logger;
import org.zeromq.ZContext;

/**
 * ZeroMQ contexts whose I/O-thread failures go to the log instead of raw stack traces on stderr
 * (JeroMQ's default). While a context terminates, JeroMQ 0.6.0's I/O threads can race: a listener
 * acknowledges its termination to a socket already reaped and hits a closed channel. That is
 * harmless, so it is logged at FINE; a clean SIGTERM must not look like a crash. Anything else is
 * a one-line warning.
 */
public final class Contexts {
    private static final Logger LOG = Logger.getLogger(Contexts.class.getName());

    private Contexts() {
    }

    public static ZContext create() {
        ZContext ctx = new ZContext();
        ctx.setUncaughtExceptionHandler(Contexts::report);
        ctx.setNotificationExceptionHandler(Contexts::report);
        return ctx;
    }

    private static void report(Thread thread, Throwable e) {
        Throwable cause = e;
        while (cause.getCause() != null && cause.getCause() != cause) {
            cause = cause.getCause();
        }
        LOG.log(cause instanceof ClosedChannelException ? Level.FINE : Level.WARNING,
                "ZeroMQ I/O thread " + thread.getName() + ": " + e);
    }
}
