package org.miron.eclipse.tests;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNotNull;
import static org.junit.Assert.assertTrue;

import java.io.File;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.jar.JarFile;
import java.util.jar.Manifest;

import javax.xml.parsers.DocumentBuilderFactory;

import org.junit.Test;
import org.w3c.dom.Document;
import org.w3c.dom.Element;
import org.w3c.dom.NodeList;

/**
 * The p2 repository built by `gradle updateSite` (build/updatesite, by Eclipse's p2 publisher):
 * its metadata (content.jar) has an installable unit for every bundle under plugins/ with the
 * version in its manifest, the feature group requiring each of them at that version, and a
 * category holding the feature; its artifact index (artifacts.jar) lists every jar; our bundles
 * carry the build's version.
 */
public class UpdateSiteTest {
    private final Path site = Path.of(System.getProperty("miron.updatesite"));
    private final String version = System.getProperty("miron.osgiVersion");

    private static Document parse(java.io.InputStream in) throws Exception {
        return DocumentBuilderFactory.newInstance().newDocumentBuilder().parse(in);
    }

    private static Document jarredXml(Path jar, String entry) throws Exception {
        try (JarFile j = new JarFile(jar.toFile())) {
            return parse(j.getInputStream(j.getEntry(entry)));
        }
    }

    private static List<Element> elements(Document doc, String tag) {
        List<Element> out = new ArrayList<>();
        NodeList list = doc.getElementsByTagName(tag);
        for (int i = 0; i < list.getLength(); i++) {
            out.add((Element) list.item(i));
        }
        return out;
    }

    /** Symbolic name -> Bundle-Version of every jar under plugins/ (named as p2 expects). */
    private Map<String, String> shippedBundles() throws Exception {
        Map<String, String> shipped = new TreeMap<>();
        for (File f : site.resolve("plugins").toFile().listFiles()) {
            try (JarFile jar = new JarFile(f)) {
                Manifest mf = jar.getManifest();
                String bsn = mf.getMainAttributes().getValue("Bundle-SymbolicName").split(";")[0].trim();
                String v = mf.getMainAttributes().getValue("Bundle-Version").trim();
                assertEquals(bsn + "_" + v + ".jar", f.getName());
                shipped.put(bsn, v);
            }
        }
        return shipped;
    }

    @Test
    public void metadataListsEveryBundleWithItsVersion() throws Exception {
        Map<String, String> shipped = shippedBundles();
        for (String ours : new String[] {"org.miron.bt", "org.miron.dsl", "org.miron.generator", "org.miron.eclipse", "org.miron.eclipse.editor"}) {
            assertEquals(ours, version, shipped.get(ours));
        }
        assertTrue(shipped.containsKey("com.fasterxml.jackson.core.jackson-databind"));

        Document content = jarredXml(site.resolve("content.jar"), "content.xml");
        Map<String, String> units = new TreeMap<>();
        for (Element unit : elements(content, "unit")) {
            units.put(unit.getAttribute("id"), unit.getAttribute("version"));
        }
        shipped.forEach((bsn, v) -> assertEquals(bsn, v, units.get(bsn)));
        assertEquals(version, units.get("org.miron.feature.feature.group"));
        assertEquals(version, units.get("org.miron.feature.feature.jar"));

        // The feature group requires every bundle at exactly its version.
        Element group = elements(content, "unit").stream()
                .filter(u -> u.getAttribute("id").equals("org.miron.feature.feature.group")).findFirst().orElseThrow();
        Map<String, String> required = new TreeMap<>();
        NodeList reqs = group.getElementsByTagName("required");
        for (int i = 0; i < reqs.getLength(); i++) {
            Element r = (Element) reqs.item(i);
            required.put(r.getAttribute("name"), r.getAttribute("range"));
        }
        shipped.forEach((bsn, v) -> assertEquals(bsn, "[" + v + "," + v + "]", required.get(bsn)));

        // A category (Install New Software... lists categorised features) holding the feature.
        Element category = elements(content, "unit").stream()
                .filter(u -> u.getAttribute("id").equals("org.miron.toolchain")).findFirst().orElseThrow();
        assertTrue(elements(content, "property").stream().anyMatch(p -> p.getParentNode().getParentNode() == category
                && p.getAttribute("name").equals("org.eclipse.equinox.p2.type.category") && p.getAttribute("value").equals("true")));
        NodeList categoryReqs = category.getElementsByTagName("required");
        assertEquals(1, categoryReqs.getLength());
        assertEquals("org.miron.feature.feature.group", ((Element) categoryReqs.item(0)).getAttribute("name"));
    }

    @Test
    public void artifactsListEveryJar() throws Exception {
        Map<String, String> shipped = shippedBundles();
        Document artifacts = jarredXml(site.resolve("artifacts.jar"), "artifacts.xml");
        Map<String, String> bundles = new TreeMap<>();
        for (Element a : elements(artifacts, "artifact")) {
            if (a.getAttribute("classifier").equals("osgi.bundle")) {
                bundles.put(a.getAttribute("id"), a.getAttribute("version"));
            } else {
                assertEquals("org.eclipse.update.feature", a.getAttribute("classifier"));
                assertEquals("org.miron.feature", a.getAttribute("id"));
                assertEquals(version, a.getAttribute("version"));
            }
        }
        assertEquals(shipped, bundles);
        assertTrue(Files.isRegularFile(site.resolve("features/org.miron.feature_" + version + ".jar")));
    }

    @Test
    public void theFeatureListsEveryBundle() throws Exception {
        Document feature = jarredXml(site.resolve("features/org.miron.feature_" + version + ".jar"), "feature.xml");
        assertEquals("org.miron.feature", feature.getDocumentElement().getAttribute("id"));
        assertEquals(version, feature.getDocumentElement().getAttribute("version"));
        Map<String, String> listed = new TreeMap<>();
        for (Element p : elements(feature, "plugin")) {
            listed.put(p.getAttribute("id"), p.getAttribute("version"));
        }
        assertEquals(shippedBundles(), listed);
    }

    @Test
    public void theP2DirectorInstallsTheFeatureWithWhatItRequires() throws Exception {
        // gradle p2InstallCheck: Eclipse's installer installed org.miron.feature from the update
        // site, with Xtext, EMF, Guice, ANTLR... from a second repository, into an empty folder.
        Path installed = Path.of(System.getProperty("miron.p2install"));
        Map<String, String> shipped = shippedBundles();
        for (Map.Entry<String, String> bundle : shipped.entrySet()) {
            Path jar = installed.resolve("plugins").resolve(bundle.getKey() + "_" + bundle.getValue() + ".jar");
            assertTrue(jar + " installed", Files.isRegularFile(jar));
        }
        assertTrue(Files.isRegularFile(installed.resolve("features/org.miron.feature_" + version + "/feature.xml")));
        try (var plugins = Files.list(installed.resolve("plugins"))) {
            List<String> names = plugins.map(p -> p.getFileName().toString()).toList();
            assertTrue(names.toString(), names.stream().anyMatch(n -> n.startsWith("org.eclipse.xtext_2.42.")));
            assertTrue(names.toString(), names.contains("org.antlr.runtime_3.2.0.jar"));
            assertTrue(names.toString(), names.stream().anyMatch(n -> n.startsWith("com.google.inject_7.")));
            assertTrue(names.toString(), names.stream().anyMatch(n -> n.startsWith("org.eclipse.emf.ecore_2.")));
        }
    }

    @Test
    public void theZipHoldsTheRepository() throws Exception {
        Path zip = site.getParent().resolve("distributions").resolve("org.miron.updatesite-" + version + ".zip");
        try (JarFile jar = new JarFile(zip.toFile())) {
            assertNotNull(jar.getEntry("content.jar"));
            assertNotNull(jar.getEntry("artifacts.jar"));
            assertNotNull(jar.getEntry("features/org.miron.feature_" + version + ".jar"));
            assertNotNull(jar.getEntry("plugins/org.miron.bt_" + version + ".jar"));
        }
    }
}
