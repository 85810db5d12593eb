package org.miron.cli.monitor;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNotNull;
import static org.junit.Assert.assertTrue;

import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.miron.runtime.Endpoints;
import org.miron.runtime.live.LiveExecutor;
import org.miron.testkit.runtime.GrootClient;

/**
 * The Groot2 server's uids land on the page's nodes: every node the page draws (a SubTree's tree
 * below its call, nested ones too, every Switch case) is found in the server's FULLTREE under the
 * same name, named SubTree calls by their name though the library writes only their _fullpath.
 */
public class GrootTreeMapTest {
    private static final Pattern NODE = Pattern.compile("<g class=\"node[^\"]*\" data-id=\"([0-9.]+)\"[^>]*>(.*?)</g>", Pattern.DOTALL);
    private static final Pattern TITLE = Pattern.compile("class=\"label-title\"[^>]*>([^<]*)<");

    @Rule
    public TemporaryFolder tmp = new TemporaryFolder();

    @Test
    public void everyNodeOfThePageHasTheServersUidUnderItsName() throws Exception {
        Path tree = tmp.getRoot().toPath().resolve("nested.xml");
        Files.writeString(tree, DebugPageBrowserTest.TREE.replace("<Script name=\"mark\" code=\"route := 'primary'\"/>",
                "<SubTree ID=\"Inner\" name=\"inner\"/><SubTree ID=\"Inner\"/>")
                .replace("</root>", "<BehaviorTree ID=\"Inner\"><Script name=\"mark\" code=\"x := 1\"/></BehaviorTree></root>"));
        int groot = GrootClient.freePortPair();
        try (LiveExecutor executor = new LiveExecutor(Endpoints.freeLoopback()).build(tree, null).serveGroot(groot);
                MonitorServer monitor = LiveMonitor.start(0, tree, Endpoints.freeLoopback(), LiveMonitor.plainNames())) {
            GrootTreeMap map = GrootTreeMap.parse(executor.groot().treeXml());
            String page = HttpClient.newHttpClient().send(HttpRequest.newBuilder(URI.create(monitor.url())).build(),
                    HttpResponse.BodyHandlers.ofString()).body();
            Matcher node = NODE.matcher(page);
            int nodes = 0;
            while (node.find()) {
                Matcher title = TITLE.matcher(node.group(2));
                assertTrue(node.group(1), title.find());
                GrootTreeMap.Entry entry = map.byPageId(node.group(1));
                assertNotNull("page node " + node.group(1) + " " + title.group(1), entry);
                assertEquals(node.group(1), title.group(1), entry.name());
                assertEquals(entry, map.byUid(entry.uid()));
                nodes++;
            }
            assertEquals("every node drawn", map.size(), nodes);
            assertEquals(1, map.rootUid());
            assertEquals("[Main, primary, primary/inner, primary/Inner::8]", map.blackboards().toString());
        }
    }

    @Test(expected = IllegalArgumentException.class)
    public void aTreeThatIsNotXmlIsRefusedWithAReason() {
        GrootTreeMap.parse("<root><BehaviorTree ID=\"Main\">");
    }
}
