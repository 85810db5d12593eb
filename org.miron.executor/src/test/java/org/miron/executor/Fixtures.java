package org.miron.executor;

import java.net.URISyntaxException;
import java.net.URL;
import java.nio.file.Path;

import org.miron.bt.bt.BTModel;

/** Loads the test .bt files through the BT language and builds trees from them. */
final class Fixtures {
    private Fixtures() {
    }

    static Path resource(String name) {
        URL url = Fixtures.class.getResource("/executor/" + name);
        if (url == null) {
            throw new IllegalArgumentException("no test resource executor/" + name);
        }
        try {
            return Path.of(url.toURI());
        } catch (URISyntaxException e) {
            throw new IllegalStateException(e);
        }
    }

    static BTModel load(String name) {
        return new BtLoader().load(resource(name)).model();
    }

    static Tree build(String file, String treeId, ActionRegistry registry, TreeContext context) {
        return new TreeBuilder(registry, context).build(load(file), treeId);
    }
}
