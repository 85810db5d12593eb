package org.miron.lsp.server;

import java.lang.reflect.Proxy;
import java.time.Duration;
import java.time.Instant;
import java.util.Locale;

import org.eclipse.lsp4j.services.LanguageClient;

/**
 * With {@code -Dmiron.lsp.timing=true}, the milestones of the server's start-up on standard error:
 * wall time since the process started and its CPU time so far, to see where an editor's wait goes
 * (docs/lsp.md, Start-up). Off by default, and then it costs nothing.
 */
final class StartupLog {
    static final boolean ON = Boolean.getBoolean("miron.lsp.timing");
    private static final Instant START = ON ? ProcessHandle.current().info().startInstant().orElse(Instant.now()) : null;
    private static volatile boolean diagnosed;

    private StartupLog() {
    }

    static void mark(String milestone) {
        if (ON) {
            long cpu = ProcessHandle.current().info().totalCpuDuration().map(Duration::toMillis).orElse(-1L);
            System.err.printf(Locale.ROOT, "miron lsp: %5d ms (CPU %5d ms) %s%n",
                    Duration.between(START, Instant.now()).toMillis(), cpu, milestone);
        }
    }

    /** The client, which marks the first diagnostics it is sent when the log is on. */
    static LanguageClient watch(LanguageClient client) {
        if (!ON) {
            return client;
        }
        return (LanguageClient) Proxy.newProxyInstance(LanguageClient.class.getClassLoader(),
                new Class<?>[] { LanguageClient.class }, (proxy, method, args) -> {
                    if (!diagnosed && method.getName().equals("publishDiagnostics")) {
                        diagnosed = true;
                        mark("first diagnostics sent");
                    }
                    try {
                        return method.invoke(client, args);
                    } catch (java.lang.reflect.InvocationTargetException e) {
                        throw e.getCause();
                    }
                });
    }
}
