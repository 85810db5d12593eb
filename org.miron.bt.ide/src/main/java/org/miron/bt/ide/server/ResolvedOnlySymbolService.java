package org.miron.bt.ide.server;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.xtext.findReferences.IReferenceFinder.IResourceAccess;
import org.eclipse.xtext.ide.server.symbol.DocumentSymbolService;
import org.eclipse.xtext.xbase.lib.Procedures.Procedure1;

/**
 * Definition and references that skip targets which resolve to nothing. In a half-written file a
 * reference's target URI (a lazy-linking proxy, or an object of a file that changed since) can
 * name no object; Xtext would build a location for null and fail the request.
 */
public class ResolvedOnlySymbolService extends DocumentSymbolService {

    @Override
    protected void doRead(IResourceAccess resourceAccess, URI objectURI, Procedure1<? super EObject> acceptor) {
        super.doRead(resourceAccess, objectURI, object -> {
            if (object != null && !object.eIsProxy()) {
                acceptor.apply(object);
            }
        });
    }
}
