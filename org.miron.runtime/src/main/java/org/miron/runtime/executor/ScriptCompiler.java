package org.miron.runtime.executor;

/** Parses version-4 scripts once, at build time, into {@link ScriptCode}. */
final class ScriptCompiler {
    private ScriptCompiler() {
    }

    /** The script, or IllegalArgumentException saying what is wrong with it. */
    static ScriptCode compile(String source) {
        throw new IllegalArgumentException("scripts are not supported yet");
    }
}
