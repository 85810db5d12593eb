package org.miron.lsp.server;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Optional;
import java.util.Set;

import org.eclipse.lsp4j.DidChangeWorkspaceFoldersParams;
import org.eclipse.lsp4j.InitializeParams;
import org.eclipse.lsp4j.WorkspaceFolder;
import org.eclipse.lsp4j.WorkspaceFoldersChangeEvent;

/**
 * The folders the server indexes: those of the client that are usable ({@link WorkspaceRoots}),
 * and, for a document opened outside all of them, the document's folder (a client without a
 * workspace, or whose root was refused). A folder added above known ones replaces them, so no file
 * is indexed twice.
 */
final class WorkspaceFolderSet {
    private final Set<Path> folders = new LinkedHashSet<>();

    /** The usable folders of initialize: workspaceFolders, else rootUri, else rootPath. */
    synchronized List<WorkspaceFolder> initial(InitializeParams params) {
        List<Optional<Path>> candidates = new ArrayList<>();
        if (params.getWorkspaceFolders() != null && !params.getWorkspaceFolders().isEmpty()) {
            params.getWorkspaceFolders().forEach(folder -> candidates.add(WorkspaceRoots.folder(folder.getUri())));
        } else if (params.getRootUri() != null) {
            candidates.add(WorkspaceRoots.folder(params.getRootUri()));
        } else if (params.getRootPath() != null) {
            candidates.add(WorkspaceRoots.folderOfPath(params.getRootPath()));
        }
        candidates.forEach(candidate -> candidate.ifPresent(this::addCovering));
        return folders.stream().map(WorkspaceFolderSet::workspaceFolder).toList();
    }

    /** The change that makes a document's folder part of the workspace, if no folder holds it yet. */
    synchronized Optional<DidChangeWorkspaceFoldersParams> cover(String documentUri) {
        Optional<Path> folder = WorkspaceRoots.folderOfDocument(documentUri);
        if (folder.isEmpty() || holds(folder.get())) {
            return Optional.empty();
        }
        List<Path> replaced = addCovering(folder.get());
        return Optional.of(new DidChangeWorkspaceFoldersParams(new WorkspaceFoldersChangeEvent(
                List.of(workspaceFolder(folder.get())), replaced.stream().map(WorkspaceFolderSet::workspaceFolder).toList())));
    }

    /** A client's change, with unusable folders left out. */
    synchronized DidChangeWorkspaceFoldersParams filter(DidChangeWorkspaceFoldersParams params) {
        List<WorkspaceFolder> added = new ArrayList<>();
        List<WorkspaceFolder> removed = new ArrayList<>();
        WorkspaceFoldersChangeEvent event = params.getEvent();
        if (event != null && event.getRemoved() != null) {
            for (WorkspaceFolder folder : event.getRemoved()) {
                WorkspaceRoots.folder(folder.getUri()).filter(folders::remove)
                        .ifPresent(path -> removed.add(workspaceFolder(path)));
            }
        }
        if (event != null && event.getAdded() != null) {
            for (WorkspaceFolder folder : event.getAdded()) {
                Optional<Path> path = WorkspaceRoots.folder(folder.getUri());
                if (path.isPresent() && !holds(path.get())) {
                    addCovering(path.get()).forEach(replaced -> removed.add(workspaceFolder(replaced)));
                    added.add(workspaceFolder(path.get()));
                }
            }
        }
        return new DidChangeWorkspaceFoldersParams(new WorkspaceFoldersChangeEvent(added, removed));
    }

    synchronized List<Path> folders() {
        return List.copyOf(folders);
    }

    private boolean holds(Path path) {
        return folders.stream().anyMatch(path::startsWith);
    }

    /** Adds a folder, dropping the known folders below it; returns those. */
    private List<Path> addCovering(Path folder) {
        if (holds(folder)) {
            return List.of();
        }
        List<Path> below = folders.stream().filter(known -> known.startsWith(folder)).toList();
        folders.removeAll(below);
        folders.add(folder);
        return below;
    }

    private static WorkspaceFolder workspaceFolder(Path folder) {
        // The path as the name: Xtext keys its projects by name, and two folders may share the last segment.
        return new WorkspaceFolder(WorkspaceRoots.uri(folder), folder.toString());
    }
}
