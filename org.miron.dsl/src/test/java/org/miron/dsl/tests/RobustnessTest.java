package org.miron.dsl.tests;

import static org.junit.Assert.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import org.eclipse.emf.common.util.BasicDiagnostic;
import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.eclipse.xtext.resource.XtextResourceSet;
import org.eclipse.xtext.validation.AbstractInjectableValidator;
import org.eclipse.xtext.validation.CheckMode;
import org.junit.After;
import org.junit.Before;
import org.junit.Test;
import org.miron.dsl.validation.CheckSet;
import org.miron.dsl.validation.MironValidator;

/**
 * Broken input gives positioned errors, never exceptions: every test model, cut short at many
 * places and with random spans deleted, is parsed, linked and validated; any exception fails.
 * Validation runs in strict mode, where checks rethrow what Xtext would silently swallow (NPEs).
 */
public class RobustnessTest {

    @Before
    public void strict() {
        System.setProperty(CheckSet.STRICT, "true");
    }

    @After
    public void lenient() {
        System.clearProperty(CheckSet.STRICT);
    }

    @Test
    public void mutilatedModelsNeverThrow() throws IOException {
        List<File> files = new ArrayList<>();
        try (Stream<java.nio.file.Path> paths = Files.walk(new File("src/test/resources/models").toPath())) {
            files.addAll(paths.map(java.nio.file.Path::toFile)
                    .filter(f -> f.getParentFile().getName().equals("valid") || f.getParentFile().getName().equals("invalid"))
                    .sorted().collect(Collectors.toList()));
        }
        files.add(new File(Models.root(), "examples/intralogistics/intralogistics.miron"));
        files.add(new File(Models.root(), "examples/hospital-delivery/hospital.miron"));
        files.add(new File(Models.root(), "examples/hospital-delivery/hospital.roqme"));
        Random random = new Random(42);
        MironValidator validator = Models.injector().getInstance(MironValidator.class);
        List<String> problems = new ArrayList<>();
        int variants = 0;
        for (File file : files) {
            String text = Files.readString(file.toPath(), StandardCharsets.UTF_8);
            List<String> mutants = new ArrayList<>();
            for (int k = 1; k < 16; k++) {
                mutants.add(text.substring(0, text.length() * k / 16));
            }
            for (int k = 0; k < 12 && text.length() > 10; k++) {
                int from = random.nextInt(text.length() - 8);
                mutants.add(text.substring(0, from) + text.substring(from + 1 + random.nextInt(8)));
            }
            for (String mutant : mutants) {
                variants++;
                try {
                    check(file, mutant, validator);
                } catch (RuntimeException | IOException e) {
                    problems.add(file.getName() + ": " + e + " at " + (e.getStackTrace().length > 0 ? e.getStackTrace()[0] : "?")
                            + "\n---\n" + mutant + "\n---");
                }
            }
        }
        assertTrue(variants > 500);
        assertTrue(problems.size() + " of " + variants + " variants failed:\n"
                + String.join("\n", problems.subList(0, Math.min(5, problems.size()))), problems.isEmpty());
    }

    private static void check(File original, String text, MironValidator validator) throws IOException {
        XtextResourceSet set = Models.injector().getInstance(XtextResourceSet.class);
        String name = original.getName();
        URI uri = URI.createFileURI(new File(original.getParentFile(), "mutant_" + name).getAbsolutePath());
        Resource resource = set.createResource(uri);
        resource.load(new ByteArrayInputStream(text.getBytes(StandardCharsets.UTF_8)), null);
        EcoreUtil.resolveAll(set);
        Models.validateAll(resource);
        String language = name.endsWith(".miron") ? "org.miron.dsl.Miron" : "org.miron.dsl.Roqme";
        Map<Object, Object> context = new HashMap<>();
        context.put(CheckMode.KEY, CheckMode.ALL);
        context.put(AbstractInjectableValidator.CURRENT_LANGUAGE_NAME, language);
        for (EObject root : resource.getContents()) {
            validator.validate(root, new BasicDiagnostic(), context);
            root.eAllContents().forEachRemaining(obj -> validator.validate(obj, new BasicDiagnostic(), context));
        }
    }
}
