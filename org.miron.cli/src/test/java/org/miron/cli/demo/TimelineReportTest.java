package org.miron.cli.demo;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.Test;
import org.miron.cli.ModelNames;
import org.miron.runtime.Json;

/** The report from hand-made bus events: a window of the run, and the requirements section. */
public class TimelineReportTest {
    private static BusRecorder.Event event(long at, String topic, String body) throws Exception {
        return new BusRecorder.Event(at, topic, Json.MAPPER.readTree(body));
    }

    private static List<BusRecorder.Event> run() throws Exception {
        List<BusRecorder.Event> e = new ArrayList<>();
        e.add(event(1000, "roqme.estimate", "{\"name\":\"safety\",\"value\":0.9}"));
        e.add(event(4000, "roqme.estimate", "{\"name\":\"safety\",\"value\":0.2}"));
        e.add(event(12000, "roqme.estimate", "{\"name\":\"safety\",\"value\":0.6}"));
        e.add(event(2000, "roqme.observation", "{\"name\":\"early\",\"actions\":[]}"));
        e.add(event(9000, "roqme.observation", "{\"name\":\"inside\",\"actions\":[]}"));
        e.add(event(3000, "miron.decision", "{\"decisions\":{\"speed\":\"slow\"},\"changed\":[\"speed\"]}"));
        e.add(event(11000, "miron.decision", "{\"decisions\":{\"speed\":\"fast\"},\"changed\":[\"speed\"]}"));
        e.add(event(25000, "miron.decision", "{\"decisions\":{\"speed\":\"slow\"},\"changed\":[\"speed\"]}"));
        e.add(event(8100, "miron.requirement", "{\"name\":\"slowNearPeople\",\"verdict\":\"violated\",\"time\":8.0,"
                + "\"detected\":8.1,\"values\":{\"roqme.HumanDistance\":1.0,\"speed\":\"fast\"}}"));
        e.add(event(14000, "miron.requirement", "{\"name\":\"slowNearPeople\",\"verdict\":\"met\",\"time\":14.0,"
                + "\"detected\":14.0,\"values\":{}}"));
        e.add(event(22000, "miron.requirement", "{\"name\":\"slowNearPeople\",\"verdict\":\"violated\",\"time\":22.0,"
                + "\"detected\":22.0,\"values\":{\"roqme.HumanDistance\":0.5,\"speed\":\"slow\"}}"));
        e.add(event(30000, "miron.requirement.status", "{\"state\":\"finished\",\"requirements\":{"
                + "\"slowNearPeople\":{\"verdict\":\"violated\",\"violations\":2},\"docks\":{\"verdict\":\"holds\",\"violations\":0}}}"));
        return e;
    }

    private static List<String> axisLabels(String html) {
        List<String> labels = new ArrayList<>();
        Matcher m = Pattern.compile("text-anchor=\"middle\" fill=\"#222\">([0-9.]+) s</text>").matcher(html);
        while (m.find()) {
            labels.add(m.group(1));
        }
        return labels;
    }

    @Test
    public void aWindowDrawsOnlyItsSpanWithAbsoluteSecondsAndTheValueHeldAtItsStart() throws Exception {
        String html = new TimelineReport("w", run(), 5000, 15000, ModelNames.none()).html();
        List<String> labels = axisLabels(html);
        assertEquals("5.0", labels.get(0));
        assertEquals("15.0", labels.get(labels.size() - 1));
        assertTrue(html, html.contains("adaptations from 5.0 s to 15.0 s"));
        // the estimate of 0.2 (from 4 s) holds at the window's start: its curve starts at the left edge
        assertTrue(html.contains("<path d=\"M150,"));
        assertTrue("the observation inside is drawn", html.contains("inside"));
        assertFalse("the one before the window is not", html.contains("early"));
        assertTrue("the adaptation inside is listed", html.contains("<td>11.0</td>"));
        assertFalse("those outside are not", html.contains("<td>3.0</td>") || html.contains("<td>25.0</td>"));
        // one violation inside (8 s), the one at 22 s is outside: one red mark, both in the table
        assertEquals(1, count(html, "<circle class=\"violation\""));
        assertTrue(html.contains("<td>slowNearPeople</td><td>8.0</td><td>8.1</td><td>14.0</td>"
                + "<td>roqme.HumanDistance = 1.0, speed = fast</td>"));
        double x8 = 150 + (960 - 150 - 20) * 3000.0 / 10000;
        assertTrue(html.contains(String.format(java.util.Locale.ROOT, "cx=\"%.1f\"", x8)));
    }

    @Test
    public void theWholeRunStartsAtZeroAndListsEveryViolationAndVerdict() throws Exception {
        String html = new TimelineReport("all", run(), 30000, ModelNames.none()).html();
        assertEquals("0.0", axisLabels(html).get(0));
        assertTrue(html.contains("adaptations in 30.0 s"));
        assertTrue(html.contains("early") && html.contains("<td>3.0</td>") && html.contains("<td>25.0</td>"));
        assertEquals(2, count(html, "<circle class=\"violation\""));
        assertEquals(2, count(html, "<tr class=\"violation\">"));
        assertTrue(html.contains("<td>docks</td><td>holds</td><td>0</td>"));
        assertTrue(html.contains("<td>slowNearPeople</td><td>violated</td><td>2</td>"));
    }

    @Test
    public void theDemosRequirementTimesAreWorldTimeOnAWallClockAxis() throws Exception {
        // at time scale 0.5 the violation at 8 s of world time is 4 s into the run
        String html = new TimelineReport("scaled", run(), 30000, ModelNames.none()).requirementTimeScale(0.5).html();
        assertTrue(html.contains("<td>slowNearPeople</td><td>4.0</td><td>4.1</td><td>7.0</td>"));
    }

    private static int count(String text, String part) {
        int n = 0;
        for (int i = text.indexOf(part); i >= 0; i = text.indexOf(part, i + 1)) {
            n++;
        }
        return n;
    }
}
