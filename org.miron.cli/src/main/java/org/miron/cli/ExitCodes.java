package org.miron.cli;

/**
 * Exit statuses the long-running commands document in their {@code --help}. A signal ends the JVM
 * with 128 + the signal number once the shutdown hooks have closed the component; a status
 * returned by {@code call()} meanwhile cannot override that (System.exit blocks while the JVM is
 * already shutting down), so the signal statuses are the ones documented. ProcessExitStatusTest
 * checks every command against its help.
 */
final class ExitCodes {
    static final String HEADING = "Exit codes:%n";
    static final String STARTUP = "2:start-up error (busy port, bad file, missing minizinc) or bad usage";
    static final String SIGINT = "130:stopped by Ctrl-C (SIGINT)";
    static final String SIGTERM = "143:stopped by SIGTERM";

    private ExitCodes() {
    }
}
