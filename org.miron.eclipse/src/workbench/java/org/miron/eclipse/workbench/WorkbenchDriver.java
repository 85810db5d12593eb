package org.miron.eclipse.workbench;

import java.io.IOException;
import java.io.InputStream;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

import org.eclipse.core.commands.ParameterizedCommand;
import org.eclipse.core.expressions.IEvaluationContext;
import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IFolder;
import org.eclipse.core.resources.IMarker;
import org.eclipse.core.resources.IProject;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.resources.ResourcesPlugin;
import org.eclipse.core.runtime.ILogListener;
import org.eclipse.core.runtime.IStatus;
import org.eclipse.core.runtime.Platform;
import org.eclipse.core.runtime.jobs.Job;
import org.eclipse.jface.action.GroupMarker;
import org.eclipse.jface.action.IContributionItem;
import org.eclipse.jface.action.MenuManager;
import org.eclipse.jface.viewers.StructuredSelection;
import org.eclipse.swt.SWT;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.Display;
import org.eclipse.swt.widgets.Event;
import org.eclipse.swt.widgets.Tree;
import org.eclipse.swt.widgets.TreeItem;
import org.eclipse.ui.IStartup;
import org.eclipse.ui.IViewPart;
import org.eclipse.ui.ide.IDE;
import org.eclipse.ui.menus.IMenuService;
import org.eclipse.ui.navigator.CommonNavigator;
import org.eclipse.ui.PlatformUI;
import org.eclipse.ui.commands.ICommandService;
import org.eclipse.ui.handlers.IHandlerService;

/**
 * Does in a real workbench what a user does, once it is up, and writes what it saw as
 * {@code key=value} lines to {@code miron.workbench.result} for WorkbenchTest, then closes the
 * workbench. The files it works with are prepared by the test ({@code miron.workbench.input}: the
 * example, a broken variant of its tree, a file that fails to parse, an .xml that is no tree).
 * Commands run through the workbench's handler service, as a menu click runs them; builds are
 * the workspace's auto-builds.
 */
public final class WorkbenchDriver implements IStartup {
    private final List<String> result = new ArrayList<>();
    private final List<String> errorLog = new ArrayList<>();
    private final List<String> platformErrors = new ArrayList<>();

    @Override
    public void earlyStartup() {
        Path out = Path.of(System.getProperty("miron.workbench.result"));
        // Errors of ours (our bundle, or our code on the stack) fail the test; the platform's are told.
        ILogListener listener = (status, plugin) -> {
            if (status.getSeverity() == IStatus.ERROR) {
                StringWriter trace = new StringWriter();
                if (status.getException() != null) {
                    status.getException().printStackTrace(new PrintWriter(trace));
                }
                boolean ours = status.getPlugin().startsWith("org.miron") || trace.toString().contains("org.miron");
                (ours ? errorLog : platformErrors).add(status.getPlugin() + ": " + status.getMessage()
                        + (status.getException() == null ? "" : " " + status.getException()));
            }
        };
        Platform.addLogListener(listener);
        try {
            run(Path.of(System.getProperty("miron.workbench.input")));
        } catch (Throwable e) {
            put("exception", e.toString());
        } finally {
            Platform.removeLogListener(listener);
            errorLog.forEach(e -> put("errorLog", e));
            platformErrors.forEach(e -> put("platformErrorLog", e));
            put("done", "true");
            try {
                Files.write(out, result, StandardCharsets.UTF_8);
            } catch (IOException e) {
                e.printStackTrace();
            }
            Display.getDefault().asyncExec(() -> PlatformUI.getWorkbench().close());
        }
    }

    private void put(String key, Object value) {
        result.add(key + "=" + String.valueOf(value).replace('\n', ' '));
    }

    private void run(Path input) throws Exception {
        long start = System.nanoTime();
        for (String bundle : List.of("org.miron.eclipse", "org.miron.eclipse.editor", "org.eclipse.ui.genericeditor")) {
            put("bundle " + bundle, Platform.getBundle(bundle) == null ? "absent" : Platform.getBundle(bundle).getState());
        }
        IProject project = ResourcesPlugin.getWorkspace().getRoot().getProject("intralogistics");
        project.create(null);
        project.open(null);
        for (String name : List.of("intralogistics.bt", "intralogistics.roqme", "intralogistics.miron", "notatree.xml")) {
            create(project.getFile(name), input.resolve(name));
        }
        ui(() -> {
            // The whole screen (no window manager under Xvfb to maximise it).
            Display.getDefault().getActiveShell().setBounds(Display.getDefault().getBounds());
            showView("org.eclipse.ui.navigator.ProjectExplorer");
        });
        settle();
        put("markersBeforeNature", markers(project).size());

        // Configure > Add MIRoN Nature, with the project selected: the menu item is there, then run.
        put("configureMenu", String.join(",", configureMenu(project)));
        execute("org.miron.eclipse.addNature", project);
        put("configureMenuAfter", String.join(",", configureMenu(project)));
        settle();
        put("nature", project.hasNature("org.miron.eclipse.nature"));
        put("builders", String.join(",", List.of(project.getDescription().getBuildSpec()).stream()
                .map(c -> c.getBuilderName()).toList()));
        put("markersValid", String.join(" | ", markers(project)));
        IFolder generated = project.getFolder("generated");
        put("generatedDerived", generated.exists() && generated.isDerived());
        put("generated", listing(generated));
        copyOut(generated, input.resolve("out/first"));

        // generated/ deleted, the tree broken: the model importing it is re-checked and writes nothing.
        generated.delete(true, null);
        settle();
        IFile tree = project.getFile("intralogistics.bt");
        tree.setContents(Files.newInputStream(input.resolve("broken/intralogistics.bt")), true, false, null);
        create(project.getFile("garbage.bt"), input.resolve("garbage.bt"));
        settle();
        put("markersBroken", String.join(" | ", markers(project)));
        put("generatedWhileBroken", generated.exists() ? listing(generated) : "absent");

        // The broken tree open at its marker and the Problems view, as the user sees them, for the
        // test's screenshot.
        ui(() -> {
            try {
                IMarker marker = tree.findMarkers("org.miron.eclipse.problem", false, IResource.DEPTH_ZERO)[0];
                IDE.openEditor(PlatformUI.getWorkbench().getActiveWorkbenchWindow().getActivePage(), marker);
            } catch (Exception e) {
                put("editor", e);
            }
            IViewPart explorer = showView("org.eclipse.ui.navigator.ProjectExplorer");
            if (explorer instanceof CommonNavigator navigator) {
                navigator.getCommonViewer().expandToLevel(project, 1);
            }
            showView("org.eclipse.ui.views.ProblemView");
        });
        TimeUnit.SECONDS.sleep(2);
        ui(WorkbenchDriver::expandProblems);
        TimeUnit.SECONDS.sleep(3);
        screenshot(Path.of(System.getProperty("miron.workbench.screenshot")));

        // The fix: the markers go, and the importer generates again.
        tree.setContents(Files.newInputStream(input.resolve("intralogistics.bt")), true, false, null);
        project.getFile("garbage.bt").delete(true, null);
        settle();
        put("markersFixed", String.join(" | ", markers(project)));
        put("generatedFixed", listing(generated));
        copyOut(generated, input.resolve("out/fixed"));

        // Generate MIRoN artefacts, on the .miron selected: the same files again.
        generated.delete(true, null);
        settle();
        execute("org.miron.generate", project.getFile("intralogistics.miron"));
        Job.getJobManager().join(org.miron.eclipse.builder.GenerateHandler.FAMILY, null);
        put("generatedByCommand", listing(generated));
        copyOut(generated, input.resolve("out/command"));
        put("seconds", (System.nanoTime() - start) / 1_000_000_000.0);
    }

    private static void create(IFile file, Path from) throws Exception {
        try (InputStream in = Files.newInputStream(from)) {
            file.create(in, true, null);
        }
    }

    /** Waits for the auto-build the last change scheduled (and anything it scheduled). */
    private static void settle() throws InterruptedException {
        for (int i = 0; i < 3; i++) {
            Job.getJobManager().wakeUp(ResourcesPlugin.FAMILY_AUTO_BUILD);
            Job.getJobManager().join(ResourcesPlugin.FAMILY_AUTO_BUILD, null);
            TimeUnit.MILLISECONDS.sleep(300);
        }
    }

    /** Runs a command through the handler service with a selection, as a context menu does. */
    private static void execute(String commandId, Object selected) throws Exception {
        Exception[] failure = new Exception[1];
        ui(() -> {
            try {
                IHandlerService handlers = PlatformUI.getWorkbench().getService(IHandlerService.class);
                ICommandService commands = PlatformUI.getWorkbench().getService(ICommandService.class);
                IEvaluationContext context = handlers.createContextSnapshot(false);
                context.addVariable("selection", new StructuredSelection(selected));
                handlers.executeCommandInContext(
                        new ParameterizedCommand(commands.getCommand(commandId), null), null, context);
            } catch (Exception e) {
                failure[0] = e;
            }
        });
        if (failure[0] != null) {
            throw failure[0];
        }
    }

    /**
     * The visible items of the Project Explorer's Configure submenu with the project selected there,
     * as the workbench's menu service fills it (its visibleWhen evaluated).
     */
    private static List<String> configureMenu(IProject project) throws Exception {
        List<String> items = new ArrayList<>();
        MenuManager menu = new MenuManager("Configure", "org.eclipse.ui.projectConfigure");
        IMenuService menus = PlatformUI.getWorkbench().getService(IMenuService.class);
        ui(() -> {
            IViewPart explorer = showView("org.eclipse.ui.navigator.ProjectExplorer");
            if (explorer instanceof CommonNavigator navigator) {
                navigator.selectReveal(new StructuredSelection(project));
            }
            menu.add(new GroupMarker("additions"));
            menus.populateContributionManager(menu, "popup:org.eclipse.ui.projectConfigure");
        });
        // The items' visibleWhen is evaluated by the workbench, after the selection's events.
        TimeUnit.MILLISECONDS.sleep(500);
        ui(() -> {
            // (e4 renders them as its own contribution items, whose id is the command's)
            for (IContributionItem item : menu.getItems()) {
                if (item.getId() != null && !(item instanceof GroupMarker)) {
                    items.add(item.getId() + ":" + (item.isVisible() ? "visible" : "hidden"));
                }
            }
            menus.releaseContributions(menu);
            menu.dispose();
        });
        return items;
    }

    /** Every MIRoN marker of the project: "file:line:start-end:severity:code:message". */
    private static List<String> markers(IProject project) throws Exception {
        List<String> found = new ArrayList<>();
        for (IMarker m : project.findMarkers("org.miron.eclipse.problem", true, IResource.DEPTH_INFINITE)) {
            found.add(m.getResource().getProjectRelativePath() + ":" + m.getAttribute(IMarker.LINE_NUMBER, -1) + ":"
                    + m.getAttribute(IMarker.CHAR_START, -1) + "-" + m.getAttribute(IMarker.CHAR_END, -1) + ":"
                    + (m.getAttribute(IMarker.SEVERITY, -1) == IMarker.SEVERITY_ERROR ? "error" : "warning") + ":"
                    + m.getAttribute("code", "") + ":" + m.getAttribute(IMarker.MESSAGE, "")
                    + (m.isSubtypeOf(IMarker.PROBLEM) ? "" : ":NOT-A-PROBLEM"));
        }
        found.sort(null);
        return found;
    }

    private static String listing(IFolder folder) throws Exception {
        if (!folder.exists()) {
            return "";
        }
        List<String> names = new ArrayList<>();
        for (IResource r : folder.members()) {
            names.add(r.getName());
        }
        names.sort(null);
        return String.join(",", names);
    }

    /** The generated files, for the test to compare with what `miron generate` writes. */
    private static void copyOut(IFolder folder, Path to) throws Exception {
        Files.createDirectories(to);
        if (folder.exists()) {
            for (IResource r : folder.members()) {
                Files.copy(r.getLocation().toFile().toPath(), to.resolve(r.getName()));
            }
        }
    }

    private static IViewPart showView(String id) {
        try {
            return PlatformUI.getWorkbench().getActiveWorkbenchWindow().getActivePage().showView(id);
        } catch (Exception e) {
            throw new IllegalStateException(e);
        }
    }

    /**
     * Opens the Problems view's severity groups, as a click on their arrows does: the SWT Expand
     * event makes JFace create the children (the view's viewer is internal API).
     */
    private static void expandProblems() {
        for (Tree tree : trees(Display.getDefault().getActiveShell())) {
            if (tree.getColumnCount() > 0 && "Description".equals(tree.getColumn(0).getText())) {
                for (TreeItem item : tree.getItems()) {
                    Event event = new Event();
                    event.item = item;
                    tree.notifyListeners(SWT.Expand, event);
                    item.setExpanded(true);
                }
            }
        }
    }

    private static List<Tree> trees(Control control) {
        List<Tree> found = new ArrayList<>();
        if (control instanceof Tree tree) {
            found.add(tree);
        }
        if (control instanceof Composite composite) {
            for (Control child : composite.getChildren()) {
                found.addAll(trees(child));
            }
        }
        return found;
    }

    private static void ui(Runnable action) {
        Display.getDefault().syncExec(action);
    }

    /** The whole X screen, as `import -window root` (ImageMagick) takes it. */
    private static void screenshot(Path png) throws Exception {
        Process p = new ProcessBuilder("import", "-window", "root", png.toString()).inheritIO().start();
        p.waitFor(30, TimeUnit.SECONDS);
    }
}
