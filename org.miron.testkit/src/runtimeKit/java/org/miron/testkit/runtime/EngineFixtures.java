package org.miron.testkit.runtime;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;

import org.junit.rules.ExternalResource;
import org.junit.rules.TemporaryFolder;

/**
 * A JUnit rule that makes {@link EngineFixture}s, each in a temporary folder of its own, and closes
 * them and deletes the folders after the test: {@code @Rule public final EngineFixtures fixtures =
 * new EngineFixtures();}, then {@code fixtures.create()} in the test.
 */
public final class EngineFixtures extends ExternalResource {
    private final TemporaryFolder folders = new TemporaryFolder();
    private final List<EngineFixture> made = new ArrayList<>();

    @Override
    protected void before() throws Throwable {
        folders.create();
    }

    @Override
    protected void after() {
        made.forEach(EngineFixture::close);
        folders.delete();
    }

    /** A fixture on the testbot model. */
    public EngineFixture create() throws IOException {
        return create("testbot");
    }

    /** A fixture on one of {@link TestModels}. */
    public EngineFixture create(String model) throws IOException {
        EngineFixture fixture = new EngineFixture(folders.newFolder().toPath(), model);
        made.add(fixture);
        return fixture;
    }
}
