package org.miron.eclipse.editor;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.nio.channels.Channels;
import java.nio.channels.Pipe;
import java.util.concurrent.Future;

import org.eclipse.lsp4e.server.StreamConnectionProvider;
import org.miron.lsp.server.MironLanguageServer;

/**
 * LSP4E's connection to the MIRoN language server, started in-process (in Eclipse's JVM, from the
 * org.miron.lsp bundle) on in-memory pipes: no external `miron` command or Java is needed. NIO
 * pipes, not java.io's piped streams, since LSP4E reads and writes from pooled threads.
 */
public final class MironStreamConnectionProvider implements StreamConnectionProvider {
    private InputStream fromServer;
    private OutputStream toServer;
    private Future<Void> listening;

    @Override
    public synchronized void start() throws IOException {
        Pipe clientToServer = Pipe.open();
        Pipe serverToClient = Pipe.open();
        toServer = Channels.newOutputStream(clientToServer.sink());
        fromServer = Channels.newInputStream(serverToClient.source());
        listening = MironLanguageServer.serve(Channels.newInputStream(clientToServer.source()),
                Channels.newOutputStream(serverToClient.sink()), false);
    }

    @Override
    public synchronized InputStream getInputStream() {
        return fromServer;
    }

    @Override
    public synchronized OutputStream getOutputStream() {
        return toServer;
    }

    @Override
    public InputStream getErrorStream() {
        return null;
    }

    @Override
    public synchronized void stop() {
        try {
            if (toServer != null) {
                toServer.close();
            }
            if (fromServer != null) {
                fromServer.close();
            }
        } catch (IOException e) {
            // Closing pipes of a server that is going away: nothing to report.
        }
        if (listening != null) {
            listening.cancel(true);
        }
    }

    // LSP4E asks for a meaningful equals/hashCode so that one definition is started once.
    @Override
    public boolean equals(Object other) {
        return other instanceof MironStreamConnectionProvider;
    }

    @Override
    public int hashCode() {
        return MironStreamConnectionProvider.class.hashCode();
    }
}
