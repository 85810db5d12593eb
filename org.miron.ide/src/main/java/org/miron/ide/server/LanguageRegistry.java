package org.miron.ide.server;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

import org.eclipse.emf.common.util.URI;
import org.eclipse.xtext.resource.IResourceServiceProvider;
import org.eclipse.xtext.resource.impl.ResourceServiceProviderRegistryImpl;

/**
 * The server's languages by file extension, where an .xml file is a behaviour tree only when it
 * looks like one: a workspace also holds pom.xml, launch files and the like, which must not be
 * parsed as BT and covered in errors. A file that does not exist yet (a new buffer) counts as BT.
 */
class LanguageRegistry extends ResourceServiceProviderRegistryImpl {
    private static final int HEAD = 4096;

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

    /** A BehaviorTree.CPP file has a root element named root; woven trees end with .ext.xml. */
    static boolean looksLikeBehaviourTree(URI uri) {
        if (!uri.isFile() || uri.lastSegment().endsWith(".ext.xml")) {
            return true;
        }
        Path path = Path.of(uri.toFileString());
        if (!Files.isRegularFile(path)) {
            return true;
        }
        try (InputStream in = Files.newInputStream(path)) {
            String head = new String(in.readNBytes(HEAD), StandardCharsets.UTF_8);
            return head.matches("(?s)\\s*(<\\?.*?\\?>\\s*)?(<!--.*?-->\\s*)*<root[\\s>/].*");
        } catch (IOException unreadable) {
            return false;
        }
    }
}
