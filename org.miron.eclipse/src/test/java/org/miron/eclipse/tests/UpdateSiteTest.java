package org.miron.eclipse.tests;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.io.File;
import java.nio.file.Files;
import java.nio.file.Path;
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
 * The update site built by `gradle updateSite` (build/updatesite): site.xml names the feature, the
 * feature lists every bundle under plugins/ with the version its manifest carries, and our bundles
 * carry the build's version.
 */
public class UpdateSiteTest {
    private final Path site = Path.of(System.getProperty("miron.updatesite"));
    private final String version = System.getProperty("miron.osgiVersion");

    private static Document parse(java.io.InputStream in) throws Exception {
        return DocumentBuilderFactory.newInstance().newDocumentBuilder().parse(in);
    }

    @Test
    public void siteFeatureAndPluginsAgree() throws Exception {
        Document siteXml = parse(Files.newInputStream(site.resolve("site.xml")));
        NodeList features = siteXml.getElementsByTagName("feature");
        assertEquals(1, features.getLength());
        Element feature = (Element) features.item(0);
        assertEquals("org.miron.feature", feature.getAttribute("id"));
        assertEquals(version, feature.getAttribute("version"));
        Path featureJar = site.resolve(feature.getAttribute("url"));
        assertTrue(featureJar + " exists", Files.isRegularFile(featureJar));

        Document featureXml;
        try (JarFile jar = new JarFile(featureJar.toFile())) {
            featureXml = parse(jar.getInputStream(jar.getEntry("feature.xml")));
        }
        assertEquals("org.miron.feature", featureXml.getDocumentElement().getAttribute("id"));
        assertEquals(version, featureXml.getDocumentElement().getAttribute("version"));
        Map<String, String> listed = new TreeMap<>();
        NodeList plugins = featureXml.getElementsByTagName("plugin");
        for (int i = 0; i < plugins.getLength(); i++) {
            Element p = (Element) plugins.item(i);
            listed.put(p.getAttribute("id"), p.getAttribute("version"));
        }

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
        assertEquals(shipped, listed);
        for (String ours : new String[] {"org.miron.bt", "org.miron.dsl", "org.miron.generator"}) {
            assertEquals(ours, version, listed.get(ours));
        }
        assertTrue(listed.containsKey("com.fasterxml.jackson.core.jackson-databind"));
    }

    @Test
    public void theZipHoldsTheSite() throws Exception {
        Path zip = site.getParent().resolve("distributions").resolve("org.miron.updatesite-" + version + ".zip");
        try (JarFile jar = new JarFile(zip.toFile())) {
            assertTrue(jar.getEntry("site.xml") != null);
            assertTrue(jar.getEntry("features/org.miron.feature_" + version + ".jar") != null);
            assertTrue(jar.getEntry("plugins/org.miron.bt_" + version + ".jar") != null);
        }
    }
}
