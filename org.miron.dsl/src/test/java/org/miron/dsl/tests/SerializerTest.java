package org.miron.dsl.tests;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EReference;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.eclipse.xtext.resource.XtextResource;
import org.eclipse.xtext.resource.XtextResourceSet;
import org.eclipse.xtext.serializer.ISerializer;
import org.junit.Test;

/**
 * Models built or changed in memory (by generators, refactorings) can be written back: parsing
 * the serialized text of a model gives an equal model.
 */
public class SerializerTest {

    private static void roundTrip(String path) throws IOException {
        roundTrip(Models.root(), path);
    }

    private static void roundTrip(File base, String path) throws IOException {
        File file = new File(base, path);
        Resource resource = Models.load(file);
        // a copy has no node model: the serializer writes it from scratch, as for a generated model
        EObject model = EcoreUtil.copy(resource.getContents().get(0));
        Resource copy = resource.getResourceSet().createResource(
                URI.createFileURI(new File(file.getParentFile(), "copy_" + file.getName()).getAbsolutePath()));
        copy.getContents().add(model);
        ISerializer serializer = ((XtextResource) resource).getResourceServiceProvider().get(ISerializer.class);
        String text = serializer.serialize(model);
        XtextResourceSet set = Models.injector().getInstance(XtextResourceSet.class);
        URI uri = URI.createFileURI(new File(file.getParentFile(), "reparsed_" + file.getName()).getAbsolutePath());
        Resource again = set.createResource(uri);
        again.load(new ByteArrayInputStream(text.getBytes(StandardCharsets.UTF_8)), null);
        assertEquals(text, List.of(), again.getErrors());
        EcoreUtil.resolveAll(set);
        assertTrue(text, new EcoreUtil.EqualityHelper() {
            private static final long serialVersionUID = 1L;

            @Override
            protected boolean haveEqualReference(EObject a, EObject b, EReference ref) {
                // cross-references point into the same imported files, loaded twice: compare by URI
                return ref.isContainment() ? super.haveEqualReference(a, b, ref)
                        : targets(a, a.eGet(ref)).equals(targets(b, b.eGet(ref)));
            }
        }.equals(model, again.getContents().get(0)));
    }

    @Test
    public void everyValidTestModel() throws IOException {
        List<String> failures = new ArrayList<>();
        try (Stream<Path> paths = Files.walk(new File("src/test/resources/models").toPath())) {
            for (Path path : paths.filter(p -> p.getParent().endsWith("valid")
                    && !p.getParent().endsWith("invalid")).sorted().collect(Collectors.toList())) {
                try {
                    roundTrip(new File("src/test/resources/models"), path.toString().substring(
                            "src/test/resources/models/".length()));
                } catch (AssertionError | RuntimeException e) {
                    failures.add(path.getFileName() + ": " + e);
                }
            }
        }
        assertEquals(String.join("\n", failures), 0, failures.size());
    }

    @Test
    public void figure3() throws IOException {
        roundTrip("examples/intralogistics/intralogistics.miron");
    }

    @Test
    public void intralogisticsRoqme() throws IOException {
        roundTrip("examples/intralogistics/intralogistics.roqme");
    }

    @Test
    public void hospital() throws IOException {
        roundTrip("examples/hospital-delivery/hospital.roqme");
        roundTrip("examples/hospital-delivery/hospital.miron");
    }

    /** A reference's targets: their fragment, and their file when it is another one than the holder's. */
    private static List<String> targets(EObject holder, Object value) {
        List<?> objects = value instanceof List ? (List<?>) value : value == null ? List.of() : List.of(value);
        return objects.stream().map(o -> {
            Resource r = ((EObject) o).eResource();
            String file = r == holder.eResource() ? "" : r.getURI().lastSegment().replaceFirst("^(copy|reparsed)_", "");
            return file + "#" + EcoreUtil.getURI((EObject) o).fragment();
        }).collect(Collectors.toList());
    }
}
