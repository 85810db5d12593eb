package org.eclipse.lsp4e.server;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;

/**
 * Compile-time and test stand-in for LSP4E's interface of the same name (LSP4E is not published to
 * Maven Central): the abstract methods a provider implements, nothing else. Never shipped: in
 * Eclipse the real interface (from org.eclipse.lsp4e) is used. The Equinox test installs it as a
 * bundle (org.miron.eclipse.lsp4estub) so that the provider can be exercised without LSP4E.
 */
public interface StreamConnectionProvider {
    void start() throws IOException;

    InputStream getInputStream();

    OutputStream getOutputStream();

    InputStream getErrorStream();

    void stop();
}
