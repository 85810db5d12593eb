package org.miron.bt.linking;

import java.io.File;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.xtext.resource.XtextResourceSet;
import org.miron.bt.bt.BehaviorTree;
import org.miron.bt.resource.BtXmlFiles;
import org.miron.bt.scoping.BtGlobalScopeProvider;
import org.miron.bt.util.BtTrees;

import com.google.inject.Inject;
import com.google.inject.Provider;
import com.google.inject.Singleton;

/**
 * Finds the include that would make an unknown SubTree ID visible: a .bt (or BT .xml) file in the same folder,
 * not included yet, that defines a tree with that ID. Sibling files are read from disk, each
 * parsed in a resource set of its own (nothing is added to the one being validated), and their
 * tree IDs are remembered per file path, modification time and size.
 */
@Singleton
public class MissingIncludes {
    /** Files whose tree IDs are remembered; beyond this the oldest are parsed again if needed. */
    private static final int REMEMBERED = 512;

    private record TreeIds(long modified, long size, Set<String> ids) {
    }

    private final Map<File, TreeIds> remembered = new LinkedHashMap<>(16, 0.75f, true) {
        @Override
        protected boolean removeEldestEntry(Map.Entry<File, TreeIds> eldest) {
            return size() > REMEMBERED;
        }
    };

    @Inject
    private Provider<XtextResourceSet> resourceSets;

    /** The include element to add, e.g. {@code <include path="nav.bt"/>}; null when no sibling defines the ID. */
    public String find(Resource resource, String treeId) {
        if (resource == null || resource.getURI() == null || !resource.getURI().isFile() || treeId == null) {
            return null;
        }
        File self = new File(resource.getURI().toFileString());
        File[] files = self.getParentFile() == null ? null : self.getParentFile().listFiles();
        if (files == null) {
            return null;
        }
        Set<URI> included = BtGlobalScopeProvider.includesOf(resource);
        List<File> siblings = new ArrayList<>();
        for (File f : files) {
            if (f.isFile() && isTreeFile(f) && !f.equals(self)
                    && !included.contains(URI.createFileURI(f.getAbsolutePath()))) {
                siblings.add(f);
            }
        }
        siblings.sort(null);
        for (File sibling : siblings) {
            if (treeIds(sibling).ids().contains(treeId)) {
                return "<include path=\"" + sibling.getName() + "\"/>";
            }
        }
        return null;
    }

    /** .bt files, and .xml files that are BehaviorTree.CPP trees (not pom.xml and the like). */
    private static boolean isTreeFile(File f) {
        return f.getName().endsWith(".bt") || f.getName().endsWith(".xml")
                && BtXmlFiles.looksLikeBehaviourTree(URI.createFileURI(f.getAbsolutePath()));
    }

    private synchronized TreeIds treeIds(File file) {
        TreeIds known = remembered.get(file);
        if (known != null && known.modified() == file.lastModified() && known.size() == file.length()) {
            return known;
        }
        TreeIds read = read(file);
        remembered.put(file, read);
        return read;
    }

    private TreeIds read(File file) {
        long modified = file.lastModified();
        long size = file.length();
        try {
            Resource sibling = resourceSets.get().getResource(URI.createFileURI(file.getAbsolutePath()), true);
            Set<String> ids = new HashSet<>();
            for (BehaviorTree tree : BtTrees.treesOf(sibling)) {
                if (tree.getName() != null) {
                    ids.add(tree.getName());
                }
            }
            return new TreeIds(modified, size, ids);
        } catch (RuntimeException e) {
            // an unreadable sibling offers no include; it is not the file being checked
            return new TreeIds(modified, size, Set.of());
        }
    }
}
