package org.miron.cli.monitor;

import java.util.function.Predicate;

import com.fasterxml.jackson.databind.JsonNode;

/** The live page's debugger in the browser: expressions evaluated until they hold, nodes found and clicked. */
final class DebugPage {
    static final String STATUS = "document.getElementById('debug-status').textContent";
    static final String MESSAGE = "document.getElementById('debug-message').textContent";

    private final HeadlessChromium browser;
    private final long timeoutMs;

    DebugPage(HeadlessChromium browser, long timeoutMs) {
        this.browser = browser;
        this.timeoutMs = timeoutMs;
    }

    void run(String script) throws Exception {
        browser.evaluate("(()=>{" + script + ";return true;})()");
    }

    /** The page id of the node named so. */
    String id(String name) throws Exception {
        return await("(Array.from(document.querySelectorAll('#tree g[data-id]')).find(g=>nodeName(g)==='" + name
                + "')||{dataset:{}}).dataset.id||''", s -> !s.isEmpty(), "node " + name + " on the page");
    }

    long pauses() throws Exception {
        return Long.parseLong(await("debug.state.pauses", s -> s.matches("\\d+"), "the pause count"));
    }

    void click(String id) throws Exception {
        run("node('" + id + "').dispatchEvent(new MouseEvent('click',{bubbles:true}))");
        awaitTrue("debug.selected==='" + id + "'", "selected " + id);
    }

    void awaitTrue(String expression, String what) throws Exception {
        await("String(" + expression + ")", s -> s.equals("true"), what);
    }

    String await(String expression, Predicate<String> holds, String what) throws Exception {
        long end = System.currentTimeMillis() + timeoutMs;
        String last = null;
        while (System.currentTimeMillis() < end) {
            JsonNode value = browser.evaluate("(()=>{try{return String(" + expression + ")}catch(e){return null}})()");
            last = value == null || value.isNull() ? null : value.asText();
            if (last != null && holds.test(last)) {
                return last;
            }
            Thread.sleep(50);
        }
        JsonNode state = browser.evaluate("JSON.stringify(debug.state)");
        JsonNode message = browser.evaluate(MESSAGE);
        throw new AssertionError(what + ": last " + last + "; debugger " + state + ", message " + message);
    }
    }
