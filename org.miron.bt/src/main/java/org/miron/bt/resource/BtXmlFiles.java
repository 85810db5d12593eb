package org.miron.bt.resource;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.regex.Pattern;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.xmi.impl.XMLResourceFactoryImpl;
import org.eclipse.xtext.resource.IResourceServiceProvider;
import org.eclipse.xtext.resource.XtextResourceFactory;
import org.miron.bt.bt.BTModel;

import com.google.inject.Injector;

/**
 * BehaviorTree.CPP trees are .xml files, like many files that are not trees (pom.xml, launch
 * files). EMF and Xtext choose a language by extension only, so .xml is registered here through
 * factories that look at the content: a file whose root element is {@code <root>} (or a woven
 * {@code .ext.xml}, or a file not written yet) is a BT file, any other .xml is left to plain XML.
 * Registered in EMF's and Xtext's global registries, so that an included .xml file gets a
 * resource and the services that describe it wherever it is loaded from: the CLI, the generator,
 * the executor, the language server and tests.
 */
public final class BtXmlFiles {
    private static final int HEAD = 4096;
    /** Optional prolog, comments and doctype, then the root element's name. */
    private static final Pattern BT_HEAD = Pattern.compile(
            "(?s)\\A\\s*(<\\?.*?\\?>\\s*)?(<!--.*?-->\\s*|<!DOCTYPE[^>]*>\\s*)*<root[\\s>/].*");

    private BtXmlFiles() {
    }

    /** Registers .xml for the BT language where nothing else claims it yet. */
    public static void register(Injector bt) {
        IResourceServiceProvider services = bt.getInstance(IResourceServiceProvider.class);
        XtextResourceFactory factory = bt.getInstance(XtextResourceFactory.class);
        IResourceServiceProvider.Registry.INSTANCE.getExtensionToFactoryMap().putIfAbsent("xml", new Services(services));
        Resource.Factory.Registry.INSTANCE.getExtensionToFactoryMap().putIfAbsent("xml", new Factory(factory));
    }

    /**
     * True when a loaded resource is a BT file: a BT model, and for .xml one whose root element is
     * root (a resource set may parse every .xml as BT, as `miron check` does with the files it is given).
     */
    public static boolean isTree(Resource resource) {
        return resource != null && !resource.getContents().isEmpty()
                && resource.getContents().get(0) instanceof BTModel
                && (!"xml".equals(resource.getURI().fileExtension()) || looksLikeBehaviourTree(resource.getURI()));
    }

    /** True for a BT file: root element {@code <root>}, a woven .ext.xml, or a file that does not exist yet. */
    public static boolean looksLikeBehaviourTree(URI uri) {
        if (uri == null || !uri.isFile() || uri.lastSegment().endsWith(".ext.xml")) {
            return true;
        }
        Path path = Path.of(uri.toFileString());
        if (!Files.isRegularFile(path)) {
            return true;
        }
        try (InputStream in = Files.newInputStream(path)) {
            return BT_HEAD.matcher(new String(in.readNBytes(HEAD), StandardCharsets.UTF_8)).matches();
        } catch (IOException unreadable) {
            return false;
        }
    }

    /**
     * The BT language's services for BT files, none for other .xml files. A named class, not a
     * lambda: JDK 17's dynamic CDS archive (the `miron` script's start-up archive) crashes on
     * this lambda's proxy class.
     */
    private static final class Services implements IResourceServiceProvider.Provider {
        private final IResourceServiceProvider bt;

        Services(IResourceServiceProvider bt) {
            this.bt = bt;
        }

        @Override
        public IResourceServiceProvider get(URI uri, String contentType) {
            return looksLikeBehaviourTree(uri) ? bt : null;
        }
    }

    /** BT resources for BT files, EMF's generic XML resources for other .xml files. */
    private static final class Factory implements Resource.Factory {
        private final Resource.Factory bt;
        private final Resource.Factory xml = new XMLResourceFactoryImpl();

        Factory(Resource.Factory bt) {
            this.bt = bt;
        }

        @Override
        public Resource createResource(URI uri) {
            return (looksLikeBehaviourTree(uri) ? bt : xml).createResource(uri);
        }
    }
}
