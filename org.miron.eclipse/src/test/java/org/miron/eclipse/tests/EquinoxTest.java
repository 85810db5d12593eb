package org.miron.eclipse.tests;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertNotNull;
import static org.junit.Assert.assertTrue;

import java.io.File;
import java.io.IOException;
import java.lang.reflect.InvocationTargetException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.ServiceLoader;
import java.util.Set;
import java.util.TreeSet;
import java.util.stream.Collectors;

import org.junit.AfterClass;
import org.junit.BeforeClass;
import org.junit.ClassRule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.miron.testkit.RepositoryRoot;
import org.osgi.framework.Bundle;
import org.osgi.framework.BundleContext;
import org.osgi.framework.BundleException;
import org.osgi.framework.Constants;
import org.osgi.framework.FrameworkEvent;
import org.osgi.framework.launch.Framework;
import org.osgi.framework.launch.FrameworkFactory;
import org.osgi.framework.wiring.FrameworkWiring;

/**
 * The toolchain in a real Equinox: the framework (org.eclipse.osgi) is started with our bundles and
 * their dependencies as bundles (Xtext 2.42, EMF, Guice, ANTLR, Guava, Jackson) and the Eclipse
 * runtime (org.eclipse.core.runtime with the extension registry and content types). The bundles'
 * classes are never on this test's class path: it reaches them through the framework, and the
 * checks that need our classes run inside it, in the test's helper bundle (org.miron.eclipse.probe,
 * called by reflection, answering in java.* types only).
 */
public class EquinoxTest {
    @ClassRule
    public static final TemporaryFolder tmp = new TemporaryFolder();

    private static final String BT = "http://www.miron.org/bt/1.0";
    private static final String ROQME = "http://www.miron.org/roqme/1.0";
    private static final String MIRON = "http://www.miron.org/miron/1.0";

    private static Framework framework;
    private static final List<Bundle> bundles = new ArrayList<>();
    private static final List<String> problems = new ArrayList<>();
    private static Class<?> probe;
    /** EPackage.Registry.INSTANCE's entries right after start-up, before any language was set up. */
    private static Map<String, String> entriesAtStart;

    @BeforeClass
    public static void startFramework() throws Exception {
        Map<String, String> config = new HashMap<>();
        config.put(Constants.FRAMEWORK_STORAGE, tmp.newFolder("storage").getAbsolutePath());
        config.put(Constants.FRAMEWORK_STORAGE_CLEAN, Constants.FRAMEWORK_STORAGE_CLEAN_ONFIRSTINIT);
        config.put("osgi.instance.area", tmp.newFolder("instance").toURI().toString());
        config.put("osgi.user.area", tmp.newFolder("user").toURI().toString());
        FrameworkFactory factory = ServiceLoader.load(FrameworkFactory.class).iterator().next();
        framework = factory.newFramework(config);
        framework.init();
        BundleContext context = framework.getBundleContext();
        context.addFrameworkListener(event -> {
            if (event.getType() == FrameworkEvent.ERROR) {
                problems.add("framework error from " + event.getBundle().getSymbolicName() + ": " + event.getThrowable());
            }
        });
        for (String path : Files.readAllLines(Path.of(System.getProperty("miron.osgi.bundles")))) {
            if (!path.isBlank()) {
                bundles.add(context.installBundle(new File(path).toURI().toString()));
            }
        }
        framework.start();
        framework.adapt(FrameworkWiring.class).resolveBundles(bundles);
        // As Eclipse's start levels do: Declarative Services first, then the content types (a DS
        // component the workspace needs when it starts), then everything else.
        List<String> first = List.of("org.apache.felix.scr", "org.eclipse.core.contenttype");
        List<Bundle> order = new ArrayList<>(bundles);
        order.sort(java.util.Comparator.comparingInt(b -> {
            int i = first.indexOf(b.getSymbolicName());
            return i < 0 ? first.size() : i;
        }));
        for (Bundle bundle : order) {
            if (bundle.getHeaders().get(Constants.FRAGMENT_HOST) != null) {
                continue;
            }
            try {
                bundle.start();
            } catch (BundleException e) {
                problems.add(bundle.getSymbolicName() + " did not start: " + e + " caused by " + e.getCause());
            }
        }
        probe = bundle("org.miron.eclipse.probe").loadClass("org.miron.eclipse.probe.Probe");
        entriesAtStart = call("ePackageEntries", List.of(BT, ROQME, MIRON));
    }

    @AfterClass
    public static void stopFramework() throws Exception {
        if (framework != null) {
            framework.stop();
            framework.waitForStop(30_000);
        }
    }

    private static Bundle bundle(String symbolicName) {
        return bundles.stream().filter(b -> symbolicName.equals(b.getSymbolicName())).findFirst()
                .orElseThrow(() -> new AssertionError(symbolicName + " is not installed"));
    }

    @SuppressWarnings("unchecked")
    private static <T> T call(String method, Object... args) throws Exception {
        for (var m : probe.getMethods()) {
            if (m.getName().equals(method) && m.getParameterCount() == args.length) {
                ClassLoader previous = Thread.currentThread().getContextClassLoader();
                try {
                    return (T) m.invoke(null, args);
                } catch (InvocationTargetException e) {
                    throw e.getCause() instanceof Exception ? (Exception) e.getCause() : e;
                } finally {
                    Thread.currentThread().setContextClassLoader(previous);
                }
            }
        }
        throw new AssertionError("no probe method " + method);
    }

    private static Path example(String name) {
        return RepositoryRoot.resolve("examples/intralogistics").resolve(name);
    }

    @Test
    public void everyBundleResolvesAndStarts() {
        List<String> notActive = bundles.stream()
                .filter(b -> b.getHeaders().get(Constants.FRAGMENT_HOST) == null && b.getState() != Bundle.ACTIVE)
                .map(b -> b.getSymbolicName() + " state " + b.getState()).collect(Collectors.toList());
        assertEquals("bundles not active", List.of(), notActive);
        assertEquals("errors while starting", List.of(), problems);
        assertTrue(bundles.size() > 25);
    }

    @Test
    public void ourBundlesCarryTheBuildsVersion() {
        String version = System.getProperty("miron.osgiVersion");
        for (String name : List.of("org.miron.bt", "org.miron.dsl", "org.miron.generator", "org.miron.bt.ide",
                "org.miron.dsl.ide", "org.miron.lsp")) {
            Bundle b = bundle(name);
            assertEquals(name, version, b.getVersion().toString());
            assertEquals(name, "JavaSE-17", b.getHeaders().get(Constants.BUNDLE_REQUIREDEXECUTIONENVIRONMENT));
        }
        assertNotNull(bundle("org.miron.bt").getEntry("plugin.xml"));
        assertNotNull(bundle("org.miron.dsl").getEntry("plugin.xml"));
        assertNotNull(bundle("org.miron.bt").getEntry("model/bt.genmodel"));
        assertNotNull(bundle("org.miron.dsl").getEntry("model/miron.genmodel"));
        assertNotNull(bundle("org.miron.dsl").getEntry("model/roqme.genmodel"));
        // The core bundles need nothing of the Eclipse workbench (LSP4E, TM4E, UI).
        for (Bundle b : bundles) {
            assertFalse(b.getSymbolicName(), b.getSymbolicName().startsWith("org.eclipse.ui")
                    || b.getSymbolicName().startsWith("org.eclipse.lsp4e") || b.getSymbolicName().startsWith("org.eclipse.tm4e"));
        }
    }

    @Test
    public void editorBundleResolvesWithoutTm4eAndLsp4eAndHoldsWhatItsPluginXmlNames() throws Exception {
        Bundle editor = bundle("org.miron.eclipse.editor");
        assertEquals(Bundle.ACTIVE, editor.getState());
        assertEquals("org.eclipse.lsp4e.server;resolution:=optional", editor.getHeaders().get(Constants.IMPORT_PACKAGE));
        assertEquals(System.getProperty("miron.osgiVersion"), editor.getVersion().toString());
        String pluginXml = new String(editor.getEntry("plugin.xml").openStream().readAllBytes(), StandardCharsets.UTF_8);
        var paths = java.util.regex.Pattern.compile("path=\"([^\"]+)\"").matcher(pluginXml);
        int count = 0;
        while (paths.find()) {
            assertNotNull(paths.group(1), editor.getEntry(paths.group(1)));
            count++;
        }
        assertEquals("3 grammars and 3 language configurations", 6, count);
        for (String type : List.of("org.miron.bt", "org.miron.roqme", "org.miron.miron")) {
            assertTrue(type, pluginXml.contains("scopeNameContentTypeBinding scopeName=") && pluginXml.contains("contentTypeId=\"" + type + "\""));
            assertTrue(type, pluginXml.contains("<contentTypeMapping id=\"org.miron.languageServer\" contentType=\"" + type + "\""));
        }
    }

    @Test
    public void extensionRegistryHoldsOurGeneratedPackages() throws Exception {
        List<String> entries = call("generatedPackages");
        assertTrue(entries.toString(), entries.contains("org.miron.bt " + BT + " org.miron.bt.bt.BtPackage"));
        assertTrue(entries.toString(), entries.contains("org.miron.dsl " + ROQME + " org.miron.dsl.roqme.RoqmePackage"));
        assertTrue(entries.toString(), entries.contains("org.miron.dsl " + MIRON + " org.miron.dsl.miron.MironPackage"));
    }

    @Test
    public void ePackageRegistryResolvesTheThreeNsUris() throws Exception {
        // Before any language was set up, the entries were EMF's descriptors made from plugin.xml
        // (EMF reads generated_package when it starts): the languages' own set-up did not put them.
        assertEquals(Map.of(BT, "descriptor", ROQME, "descriptor", MIRON, "descriptor"), entriesAtStart);
        Map<String, String> found = call("ePackages", List.of(BT, ROQME, MIRON));
        assertEquals("org.miron.bt org.miron.bt.bt.impl.BtPackageImpl", found.get(BT));
        assertEquals("org.miron.dsl org.miron.dsl.roqme.impl.RoqmePackageImpl", found.get(ROQME));
        assertEquals("org.miron.dsl org.miron.dsl.miron.impl.MironPackageImpl", found.get(MIRON));
    }

    @Test
    public void contentTypesOfTheThreeLanguages() throws Exception {
        assertEquals("org.miron.bt", call("contentType", "tree.bt"));
        assertEquals("org.miron.roqme", call("contentType", "robot.roqme"));
        assertEquals("org.miron.miron", call("contentType", "robot.miron"));
    }

    @Test
    public void emfLoadsOurFilesThroughTheExtensionParsers() throws Exception {
        String miron = call("loadWithEmf", example("intralogistics.miron").toString());
        assertTrue(miron, miron.matches("org\\.eclipse\\.xtext\\.\\S*Resource MironModel 0"));
        String bt = call("loadWithEmf", example("intralogistics.bt").toString());
        assertTrue(bt, bt.matches("org\\.eclipse\\.xtext\\.\\S*Resource BTModel 0"));
    }

    @Test
    public void theIntralogisticsExampleValidates() throws Exception {
        List<String> diagnostics = call("check", List.of(example("intralogistics.miron").toString()));
        assertEquals(List.of(), diagnostics.stream().filter(d -> d.contains("error")).collect(Collectors.toList()));
    }

    @Test
    public void aBrokenCopyHasErrors() throws Exception {
        Path dir = tmp.newFolder("broken").toPath();
        for (String name : List.of("intralogistics.miron", "intralogistics.roqme", "intralogistics.bt")) {
            Files.copy(example(name), dir.resolve(name));
        }
        Path miron = dir.resolve("intralogistics.miron");
        Files.writeString(miron, Files.readString(miron).replaceFirst("import", "imprt"), StandardCharsets.UTF_8);
        List<String> diagnostics = call("check", List.of(miron.toString()));
        assertTrue(diagnostics.toString(), diagnostics.stream().anyMatch(d -> d.contains("error")));
    }

    @Test
    public void theLanguageServerAnswersInitializeInsideOsgi() throws Exception {
        String response = call("lspInitialize", example("intralogistics.miron").getParent().toString());
        assertTrue(response, response.contains("\"result\"") && response.contains("\"capabilities\""));
        assertTrue(response, response.contains("completionProvider"));
        assertTrue(response, response.contains("miron.generate"));
        assertTrue(response, response.contains("miron.convert")); // the BT language's command (source action)
    }

    @Test
    public void lsp4eProviderStartsTheServerInProcess() throws Exception {
        // The class LSP4E instantiates from plugin.xml (here against the LSP4E stand-in bundle).
        Bundle editor = bundle("org.miron.eclipse.editor");
        String pluginXml = new String(editor.getEntry("plugin.xml").openStream().readAllBytes(), StandardCharsets.UTF_8);
        String cls = "org.miron.eclipse.editor.MironStreamConnectionProvider";
        assertTrue(pluginXml.contains("class=\"" + cls + "\""));
        Class<?> type = editor.loadClass(cls);
        Object provider = type.getConstructor().newInstance();
        type.getMethod("start").invoke(provider);
        try {
            java.io.OutputStream out = (java.io.OutputStream) type.getMethod("getOutputStream").invoke(provider);
            java.io.InputStream in = (java.io.InputStream) type.getMethod("getInputStream").invoke(provider);
            String uri = example("intralogistics.miron").getParent().toUri().toString();
            String response = Lsp.request(out, in, 1, "initialize",
                    "{\"processId\":null,\"rootUri\":\"" + uri + "\",\"capabilities\":{}}");
            assertTrue(response, response.contains("\"capabilities\"") && response.contains("miron.generate"));
        } finally {
            type.getMethod("stop").invoke(provider);
        }
    }

    @Test
    public void theBuilderMarksABrokenImportAndGeneratesItsImporterAgainOnceFixed() throws Exception {
        String tree = Files.readString(example("intralogistics.bt"));
        String broken = tree.replace("<SubTreePlus ID=\"GoTo\" __shared_blackboard=\"false\" x_input=\"-9.33\"",
                "<SubTreePlus ID=\"GoTooo\" __shared_blackboard=\"false\" x_input=\"-9.33\"");
        assertFalse(broken.equals(tree));
        List<String> result = call("buildWithNature", example("intralogistics.miron").getParent().toString(), broken);
        String six = "generated: intralogistics.dzn intralogistics.ext.xml intralogistics.io.json intralogistics.mzn"
                + " intralogistics.requirements.json intralogistics.roqme.json";
        assertEquals(List.of("markers: ", six, "markers: intralogistics.bt:17:bt.unknown-subtree", "generated: ",
                "markers: ", six), result);
    }

    @Test
    public void generateCommandWritesTheSixFilesThroughTheCore() throws Exception {
        String broken = Files.readString(example("intralogistics.miron")).replaceFirst("import", "imprt");
        List<String> result = call("generateThroughCommand", example("intralogistics.miron").getParent().toString(), broken);
        // Six files in generated/ (tree, mzn, dzn, io.json, requirements.json, roqme.json), refreshed
        // into the workspace; then the broken copy's status.
        assertEquals(result.toString(), 7, result.size());
        assertTrue(result.toString(), result.subList(0, 6).stream().anyMatch(f -> f.endsWith(".io.json")));
        assertTrue(result.toString(), result.subList(0, 6).stream().anyMatch(f -> f.endsWith(".mzn")));
        assertTrue(result.toString(), result.subList(0, 6).stream().anyMatch(f -> f.endsWith(".requirements.json")));
        assertTrue(result.toString(), result.subList(0, 6).stream().anyMatch(f -> f.endsWith(".roqme.json")));
        assertTrue(result.get(6), result.get(6).startsWith("ERROR Not generated: broken.miron has"));
    }

    @Test
    public void theGeneratorWritesTheSixFiles() throws Exception {
        Path out = tmp.newFolder("generated").toPath();
        List<String> result = call("generate", List.of(example("intralogistics.miron").toString()), out.toString());
        assertEquals(result.toString(), "WRITTEN", result.get(0));
        TreeSet<String> files = new TreeSet<>();
        try (var list = Files.list(out)) {
            list.forEach(p -> files.add(p.getFileName().toString()));
        }
        assertEquals(files.toString(), Set.of("intralogistics.ext.xml", "intralogistics.mzn", "intralogistics.dzn",
                "intralogistics.io.json", "intralogistics.requirements.json", "intralogistics.roqme.json"), files);
        for (String f : files) {
            assertTrue(f, Files.size(out.resolve(f)) > 0);
        }
    }

    static String read(Path p) throws IOException {
        return Files.readString(p);
    }
}
