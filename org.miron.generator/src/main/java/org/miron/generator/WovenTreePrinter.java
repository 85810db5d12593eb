package org.miron.generator;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.resource.ResourceSet;
import org.eclipse.xtext.resource.IResourceFactory;
import org.eclipse.xtext.resource.IResourceServiceProvider;
import org.miron.bt.bt.BTModel;
import org.miron.bt.formatting2.BtFormatting;

/**
 * Prints the woven tree as `miron format` prints a tree: through the BT language's serializer and
 * formatter (BtFormatting), after the XML prolog and a comment, which are not part of the model.
 */
public class WovenTreePrinter {

    /**
     * The tree as the text of the file at location. While printing, the tree sits in a BT resource
     * at location in resourceSet (the set holding the trees it includes and calls): cross-references
     * are written by the names in scope there. The resource set is left as it was.
     */
    public String print(BTModel tree, URI location, ResourceSet resourceSet, String comment) {
        IResourceServiceProvider bt = IResourceServiceProvider.Registry.INSTANCE
                .getResourceServiceProvider(URI.createURI("woven.bt"));
        if (bt == null) {
            throw new IllegalStateException("the BT language is not set up (BtStandaloneSetup)");
        }
        Resource resource = bt.get(IResourceFactory.class).createResource(location);
        resourceSet.getResources().add(resource);
        try {
            resource.getContents().add(tree);
            // "--" may not occur in an XML comment
            return "<?xml version=\"1.0\"?>\n<!-- " + comment.replace("--", "- -") + " -->\n" + BtFormatting.print(tree);
        } finally {
            resourceSet.getResources().remove(resource);
        }
    }
}
