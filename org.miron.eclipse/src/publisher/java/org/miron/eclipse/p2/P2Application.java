package org.miron.eclipse.p2;

import java.io.File;
import java.lang.reflect.Method;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.ServiceLoader;

import org.osgi.framework.Bundle;
import org.osgi.framework.BundleContext;
import org.osgi.framework.Constants;
import org.osgi.framework.launch.Framework;
import org.osgi.framework.launch.FrameworkFactory;

/**
 * Runs one of Eclipse's own p2 applications headlessly, as Eclipse's launcher would: starts an
 * Equinox with the p2 bundles (from Maven Central), then calls the application's
 * {@code run(String[])}. Used by the build for the p2 publishers (the update site) and the p2
 * director (installing the feature from it, as Install New Software... does).
 *
 * <p>Arguments: the file listing the p2 bundles (one path a line), the work folder for the
 * framework, the symbolic name of the bundle holding the application, its class, then the
 * application's own arguments. Exits with 0 when the application answers IApplication.EXIT_OK.
 */
public final class P2Application {
    private P2Application() {
    }

    public static void main(String[] args) throws Exception {
        List<String> bundlePaths = Files.readAllLines(Path.of(args[0]));
        Path work = Path.of(args[1]);
        String bundleName = args[2];
        String applicationClass = args[3];
        String[] applicationArgs = Arrays.copyOfRange(args, 4, args.length);

        Map<String, String> config = new HashMap<>();
        config.put(Constants.FRAMEWORK_STORAGE, work.resolve("storage").toString());
        config.put(Constants.FRAMEWORK_STORAGE_CLEAN, Constants.FRAMEWORK_STORAGE_CLEAN_ONFIRSTINIT);
        config.put("osgi.instance.area", work.resolve("instance").toUri().toString());
        config.put("eclipse.p2.data.area", work.resolve("p2").toUri().toString());
        // As when Eclipse itself starts (EclipseStarter): some p2 bundles use the JDK's XML classes
        // without importing them.
        config.put("osgi.compatibility.bootdelegation", "true");
        Framework framework = ServiceLoader.load(FrameworkFactory.class).iterator().next().newFramework(config);
        framework.init();
        BundleContext context = framework.getBundleContext();
        List<Bundle> bundles = new ArrayList<>();
        for (String path : bundlePaths) {
            if (!path.isBlank()) {
                bundles.add(context.installBundle(new File(path).toURI().toString()));
            }
        }
        framework.start();
        int status = 1;
        try {
            // Declarative Services first (p2's agent and repository managers are DS components).
            bundles.sort((a, b) -> Boolean.compare(!"org.apache.felix.scr".equals(a.getSymbolicName()),
                    !"org.apache.felix.scr".equals(b.getSymbolicName())));
            for (Bundle bundle : bundles) {
                if (bundle.getHeaders().get(Constants.FRAGMENT_HOST) == null) {
                    bundle.start();
                }
            }
            Bundle holder = bundles.stream().filter(b -> bundleName.equals(b.getSymbolicName())).findFirst()
                    .orElseThrow(() -> new IllegalArgumentException(bundleName + " is not among the bundles"));
            Class<?> app = holder.loadClass(applicationClass);
            Object application = app.getConstructor().newInstance();
            Method run = app.getMethod("run", String[].class);
            Object result = run.invoke(application, (Object) applicationArgs);
            // IApplication.EXIT_OK is Integer 0.
            status = Integer.valueOf(0).equals(result) ? 0 : 1;
            if (status != 0) {
                System.err.println(applicationClass + " answered " + result);
            }
        } finally {
            framework.stop();
            framework.waitForStop(30_000);
        }
        System.exit(status);
    }
}
