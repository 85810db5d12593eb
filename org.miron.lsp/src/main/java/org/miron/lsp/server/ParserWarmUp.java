package org.miron.lsp.server;

import java.util.List;

import org.eclipse.emf.ecore.impl.EFactoryImpl;
import org.miron.bt.parser.antlr.internal.InternalBtParser;
import org.miron.bt.parser.antlr.internal.InternalBtScriptParser;
import org.miron.bt.parser.antlr.lexer.InternalBtLexer;
import org.miron.dsl.parser.antlr.internal.InternalMironLexer;
import org.miron.dsl.parser.antlr.internal.InternalMironParser;
import org.miron.dsl.parser.antlr.internal.InternalRoqmeLexer;
import org.miron.dsl.parser.antlr.internal.InternalRoqmeParser;

/**
 * Initializes, on a thread of its own while the languages are set up, classes whose static
 * initialization costs the first file noticeably (docs/lsp.md, Start-up): EMF's factory base class
 * (its date formats load the JDK's locale and time-zone data) and the ANTLR lexers and parsers
 * (their tables are unpacked at class initialization). None of them touches EMF's registries,
 * so it is safe beside the set-up; a failure costs only the saving.
 */
final class ParserWarmUp {
    private static final List<Class<?>> CLASSES = List.of(EFactoryImpl.class, InternalBtLexer.class,
            InternalBtParser.class, InternalMironLexer.class, InternalMironParser.class, InternalRoqmeLexer.class,
            InternalRoqmeParser.class, InternalBtScriptParser.class);

    private ParserWarmUp() {
    }

    static void start() {
        Thread thread = new Thread(ParserWarmUp::run, "miron-lsp-warm-up");
        thread.setDaemon(true);
        thread.start();
    }

    private static void run() {
        for (Class<?> type : CLASSES) {
            try {
                Class.forName(type.getName(), true, type.getClassLoader());
            } catch (ClassNotFoundException | LinkageError e) {
                return; // the set-up initializes it itself when needed
            }
        }
        StartupLog.mark("parsers warmed up");
    }
}
