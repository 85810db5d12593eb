package org.miron.eclipse.probe;

import java.io.File;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

import org.eclipse.core.runtime.IConfigurationElement;
import org.eclipse.core.runtime.Platform;
import org.eclipse.core.runtime.RegistryFactory;
import org.eclipse.core.runtime.content.IContentType;
import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.EPackage;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.resource.impl.ResourceSetImpl;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.miron.generator.WeightPolicy;
import org.miron.generator.standalone.BatchGeneration;
import org.miron.generator.standalone.ModelLoader;
import org.osgi.framework.Bundle;
import org.osgi.framework.FrameworkUtil;

/**
 * Test helper bundle of the Equinox test: runs inside the framework, against the MIRoN bundles and
 * Eclipse's registries, and answers in java.* types only (the test, outside the framework, calls
 * these static methods by reflection and cannot share any other class with the bundles).
 */
public final class Probe {
    private Probe() {
    }

    /** Entries of EMF's generated_package extension point: "contributor uri class". */
    public static List<String> generatedPackages() {
        List<String> entries = new ArrayList<>();
        for (IConfigurationElement e : RegistryFactory.getRegistry()
                .getConfigurationElementsFor("org.eclipse.emf.ecore", "generated_package")) {
            entries.add(e.getContributor().getName() + " " + e.getAttribute("uri") + " " + e.getAttribute("class"));
        }
        return entries;
    }

    /** nsURI -> "bundle class" of the EPackage that EPackage.Registry.INSTANCE resolves it to. */
    public static Map<String, String> ePackages(List<String> nsUris) {
        Map<String, String> found = new TreeMap<>();
        for (String nsUri : nsUris) {
            EPackage p = EPackage.Registry.INSTANCE.getEPackage(nsUri);
            if (p != null) {
                Bundle bundle = FrameworkUtil.getBundle(p.getClass());
                found.put(nsUri, (bundle == null ? "?" : bundle.getSymbolicName()) + " " + p.getClass().getName());
            }
        }
        return found;
    }

    /**
     * nsURI -> how EPackage.Registry.INSTANCE holds it before anything resolved it: "descriptor"
     * (registered from plugin.xml, resolved on first use), "package" or "absent".
     */
    public static Map<String, String> ePackageEntries(List<String> nsUris) {
        Map<String, String> found = new TreeMap<>();
        for (String nsUri : nsUris) {
            Object entry = EPackage.Registry.INSTANCE.get(nsUri);
            found.put(nsUri, entry == null ? "absent" : entry instanceof EPackage ? "package" : "descriptor");
        }
        return found;
    }

    /** The id of the content type Eclipse gives a file name, or null. */
    public static String contentType(String fileName) {
        IContentType type = Platform.getContentTypeManager().findContentTypeFor(fileName);
        return type == null ? null : type.getId();
    }

    /**
     * Loads a file through EMF's global registry only (a plain ResourceSetImpl: the factory comes
     * from the extension_parser registration) and answers "resourceClass rootClass errors".
     */
    public static String loadWithEmf(String file) {
        Resource r = new ResourceSetImpl().getResource(URI.createFileURI(new File(file).getAbsolutePath()), true);
        EcoreUtil.resolveAll(r);
        return r.getClass().getName() + " " + (r.getContents().isEmpty() ? "-" : r.getContents().get(0).eClass().getName())
                + " " + r.getErrors().size();
    }

    /** Loads and validates the files with the MIRoN languages: the diagnostics, one string each. */
    public static List<String> check(List<String> files) {
        ModelLoader loader = new ModelLoader();
        files.forEach(f -> loader.load(new File(f)));
        List<String> out = new ArrayList<>();
        loader.validateAll().forEach(d -> out.add(d.toString()));
        return out;
    }

    /**
     * Starts the MIRoN language server in this framework on in-memory pipes, sends LSP's
     * initialize request for the workspace folder and answers the server's raw JSON response.
     */
    public static String lspInitialize(String workspace) throws Exception {
        java.io.PipedOutputStream toServer = new java.io.PipedOutputStream();
        java.io.PipedInputStream serverIn = new java.io.PipedInputStream(toServer, 1 << 16);
        java.io.PipedOutputStream serverOut = new java.io.PipedOutputStream();
        java.io.PipedInputStream fromServer = new java.io.PipedInputStream(serverOut, 1 << 16);
        java.util.concurrent.Future<Void> listening = org.miron.lsp.server.MironLanguageServer.serve(serverIn, serverOut, false);
        try {
            String uri = new File(workspace).toURI().toString();
            String request = "{\"jsonrpc\":\"2.0\",\"id\":1,\"method\":\"initialize\",\"params\":{\"processId\":null,"
                    + "\"rootUri\":\"" + uri + "\",\"capabilities\":{}}}";
            byte[] body = request.getBytes(java.nio.charset.StandardCharsets.UTF_8);
            toServer.write(("Content-Length: " + body.length + "\r\n\r\n").getBytes(java.nio.charset.StandardCharsets.US_ASCII));
            toServer.write(body);
            toServer.flush();
            // Messages until the response to id 1 (the server may log or notify first).
            while (true) {
                int length = -1;
                StringBuilder line = new StringBuilder();
                while (true) {
                    int c = fromServer.read();
                    if (c < 0) {
                        throw new java.io.EOFException("the server closed the connection");
                    }
                    if (c == '\n') {
                        String header = line.toString().trim();
                        if (header.isEmpty()) {
                            break;
                        }
                        if (header.toLowerCase().startsWith("content-length:")) {
                            length = Integer.parseInt(header.substring(15).trim());
                        }
                        line.setLength(0);
                    } else {
                        line.append((char) c);
                    }
                }
                String message = new String(fromServer.readNBytes(length), java.nio.charset.StandardCharsets.UTF_8);
                if (message.contains("\"id\":1") && (message.contains("\"result\"") || message.contains("\"error\""))) {
                    return message;
                }
            }
        } finally {
            toServer.close();
            listening.cancel(true);
        }
    }

    /**
     * The "Generate MIRoN artefacts" handler (bundle org.miron.eclipse), headless: a workspace project with
     * copies of the example's files, the handler executed on the .miron file selected, its job
     * awaited; answers the files of generated/ as the workspace sees them, then the status of
     * generating a broken copy ("severity message").
     */
    public static List<String> generateThroughCommand(String exampleDir, String brokenModelText) throws Exception {
        org.eclipse.core.resources.IWorkspace workspace = org.eclipse.core.resources.ResourcesPlugin.getWorkspace();
        org.eclipse.core.resources.IProject project = workspace.getRoot().getProject("intralogistics");
        project.create(null);
        project.open(null);
        for (File f : new File(exampleDir).listFiles(File::isFile)) {
            try (java.io.InputStream in = new java.io.FileInputStream(f)) {
                project.getFile(f.getName()).create(in, true, null);
            }
        }
        org.eclipse.core.resources.IFile model = project.getFile("intralogistics.miron");
        org.eclipse.core.expressions.EvaluationContext context = new org.eclipse.core.expressions.EvaluationContext(null, model);
        context.addVariable("selection", List.of(model));
        new org.miron.eclipse.builder.GenerateHandler()
                .execute(new org.eclipse.core.commands.ExecutionEvent(null, Map.of(), null, context));
        org.eclipse.core.runtime.jobs.Job.getJobManager().join(org.miron.eclipse.builder.GenerateHandler.FAMILY, null);
        List<String> out = new ArrayList<>();
        org.eclipse.core.resources.IFolder generated = project.getFolder("generated");
        if (generated.exists()) {
            for (org.eclipse.core.resources.IResource r : generated.members()) {
                out.add(r.getName());
            }
        }
        java.util.Collections.sort(out);
        org.eclipse.core.resources.IFile broken = project.getFile("broken.miron");
        broken.create(new java.io.ByteArrayInputStream(brokenModelText.getBytes(java.nio.charset.StandardCharsets.UTF_8)), true, null);
        org.eclipse.core.runtime.IStatus status = org.miron.eclipse.builder.ArtefactGeneration.generate(broken);
        out.add((status.getSeverity() == org.eclipse.core.runtime.IStatus.ERROR ? "ERROR " : "NOT-ERROR ") + status.getMessage());
        return out;
    }

    /**
     * The builder, headless: a project with copies of the example's model files, the MIRoN nature
     * added, built; then its tree replaced with brokenTree and built again (incrementally); then
     * restored and built. Answers, for each of the three builds, "markers: file:line:code ..." and
     * "generated: names".
     */
    public static List<String> buildWithNature(String exampleDir, String brokenTree) throws Exception {
        // Builds only when asked, so each one sees its change (the workbench test has auto-builds).
        org.eclipse.core.resources.IWorkspace workspace = org.eclipse.core.resources.ResourcesPlugin.getWorkspace();
        org.eclipse.core.resources.IWorkspaceDescription description = workspace.getDescription();
        description.setAutoBuilding(false);
        workspace.setDescription(description);
        org.eclipse.core.resources.IProject project =
                org.eclipse.core.resources.ResourcesPlugin.getWorkspace().getRoot().getProject("built");
        project.create(null);
        project.open(null);
        for (String name : List.of("intralogistics.bt", "intralogistics.roqme", "intralogistics.miron")) {
            try (java.io.InputStream in = new java.io.FileInputStream(new File(exampleDir, name))) {
                project.getFile(name).create(in, true, null);
            }
        }
        org.miron.eclipse.builder.MironNature.addTo(project);
        List<String> out = new ArrayList<>();
        project.build(org.eclipse.core.resources.IncrementalProjectBuilder.FULL_BUILD, null);
        describe(project, out);
        org.eclipse.core.resources.IFile tree = project.getFile("intralogistics.bt");
        byte[] good = java.nio.file.Files.readAllBytes(new File(exampleDir, "intralogistics.bt").toPath());
        project.getFolder("generated").delete(true, null);
        tree.setContents(new java.io.ByteArrayInputStream(brokenTree.getBytes(java.nio.charset.StandardCharsets.UTF_8)),
                true, false, null);
        project.build(org.eclipse.core.resources.IncrementalProjectBuilder.INCREMENTAL_BUILD, null);
        describe(project, out);
        tree.setContents(new java.io.ByteArrayInputStream(good), true, false, null);
        project.build(org.eclipse.core.resources.IncrementalProjectBuilder.INCREMENTAL_BUILD, null);
        describe(project, out);
        return out;
    }

    private static void describe(org.eclipse.core.resources.IProject project, List<String> out) throws Exception {
        List<String> markers = new ArrayList<>();
        for (org.eclipse.core.resources.IMarker m : project.findMarkers("org.miron.eclipse.problem", true,
                org.eclipse.core.resources.IResource.DEPTH_INFINITE)) {
            markers.add(m.getResource().getName() + ":" + m.getAttribute(org.eclipse.core.resources.IMarker.LINE_NUMBER, 0)
                    + ":" + m.getAttribute("code", ""));
        }
        java.util.Collections.sort(markers);
        out.add("markers: " + String.join(" ", markers));
        List<String> names = new ArrayList<>();
        org.eclipse.core.resources.IFolder generated = project.getFolder("generated");
        if (generated.exists()) {
            for (org.eclipse.core.resources.IResource r : generated.members()) {
                names.add(r.getName());
            }
        }
        java.util.Collections.sort(names);
        out.add("generated: " + String.join(" ", names));
    }

    /** Generates the .miron files into dir: the stage, then the names written. */
    public static List<String> generate(List<String> files, String dir) {
        ModelLoader loader = new ModelLoader();
        List<Resource> resources = new ArrayList<>();
        files.forEach(f -> resources.add(loader.load(new File(f))));
        BatchGeneration.Outcome outcome = new BatchGeneration(loader, WeightPolicy.NEED)
                .run(resources, BatchGeneration.folder(Path.of(dir)));
        List<String> out = new ArrayList<>();
        out.add(outcome.stage().name());
        out.addAll(outcome.written());
        outcome.validation().forEach(d -> out.add(d.toString()));
        outcome.generationErrors().forEach(d -> out.add(d.toString()));
        return out;
    }
}
