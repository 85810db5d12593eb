package org.miron.lsp.server;

import org.eclipse.emf.common.util.URI;
import org.eclipse.xtext.resource.IResourceServiceProvider;
import org.eclipse.xtext.resource.impl.ResourceServiceProviderRegistryImpl;
import org.miron.bt.resource.BtXmlFiles;

/**
 * The server's languages by file extension, where an .xml file is a behaviour tree only when it
 * looks like one: a workspace also holds pom.xml, launch files and the like, which must not be
 * parsed as BT and covered in errors. A file that does not exist yet (a new buffer) counts as BT.
 */
class LanguageRegistry extends ResourceServiceProviderRegistryImpl {
    @Override
    public IResourceServiceProvider getResourceServiceProvider(URI uri, String contentType) {
        if (uri != null && "xml".equals(uri.fileExtension()) && !looksLikeBehaviourTree(uri)) {
            return null;
        }
        return super.getResourceServiceProvider(uri, contentType);
    }

    @Override
    public IResourceServiceProvider getResourceServiceProvider(URI uri) {
        return getResourceServiceProvider(uri, null);
    }

    /** A BehaviorTree.CPP file has a root element named root; woven trees end with .ext.xml (BtXmlFiles). */
    static boolean looksLikeBehaviourTree(URI uri) {
        return BtXmlFiles.looksLikeBehaviourTree(uri);
    }
}
