package org.miron.bt.ide.server;

import java.util.concurrent.CompletionException;
import java.util.concurrent.ExecutionException;

import org.eclipse.lsp4j.WorkspaceEdit;
import org.eclipse.lsp4j.jsonrpc.ResponseErrorException;
import org.eclipse.xtext.ide.server.rename.RenameService2;
import org.eclipse.xtext.xbase.lib.Exceptions;

/**
 * Xtext's rename, with its refusal ("Refactoring cannot be performed", e.g. on a name that is not
 * a declaration or in a file that does not parse) answered as that LSP error. Xtext throws it
 * wrapped in an ExecutionException, which LSP4J turns into an internal error with a stack trace.
 */
public class PlainErrorRenameService extends RenameService2 {

    @Override
    public WorkspaceEdit rename(Options options) {
        try {
            return super.rename(options);
        } catch (Exception e) {
            Throwable cause = e;
            while ((cause instanceof ExecutionException || cause instanceof CompletionException) && cause.getCause() != null) {
                cause = cause.getCause();
            }
            if (cause instanceof ResponseErrorException) {
                throw (ResponseErrorException) cause;
            }
            throw Exceptions.sneakyThrow(e);
        }
    }
}
