package org.miron.lsp.server;

import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.xtext.generator.IShouldGenerate;
import org.eclipse.xtext.util.CancelIndicator;

/**
 * The server's builder generates nothing (none of the three languages binds a generator;
 * `miron.generate` runs the generators on request). Xtext's default would validate every file it
 * builds a second time, on every change, only to decide to run a generator that does nothing.
 */
final class NothingToGenerate implements IShouldGenerate {
    @Override
    public boolean shouldGenerate(Resource resource, CancelIndicator cancelIndicator) {
        return false;
    }
}
