package org.miron.cli.demo;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.miron.runtime.Endpoints;
import org.miron.runtime.requirement.LiveRequirements;
import org.miron.runtime.requirement.RequirementEvent;
import org.miron.runtime.requirement.RequirementModel;
import org.miron.runtime.requirement.RequirementResult;
import org.miron.runtime.requirement.Verdict;

/**
 * The demo's requirement checks: {@link LiveRequirements} beside the engine, on world time (the
 * recorder's clock at the demo's time scale, so that a model's {@code within 5 seconds} is five
 * seconds of the world), each event told on the console at its instant on the console's axis, and
 * one verdict line per requirement at the end.
 */
public final class DemoRequirements implements AutoCloseable {
    static final String WHO = "REQ   ";
    private final LiveRequirements live;
    private final Narrator narrator;
    private final BusRecorder recorder;
    private final double timeScale;

    /**
     * The generated {@code name.requirements.json} of {@code generated}, or null when there is none
     * or it states no requirement (then the demo checks nothing).
     */
    public static RequirementModel load(Path generated, String name) {
        Path file = generated.resolve(name + ".requirements.json");
        if (!Files.isRegularFile(file)) {
            return null;
        }
        RequirementModel model = RequirementModel.load(file);
        return model.requirements().isEmpty() ? null : model;
    }

    private DemoRequirements(RequirementModel model, Endpoints endpoints, BusRecorder recorder, double timeScale,
            Narrator narrator) {
        this.narrator = narrator;
        this.recorder = recorder;
        this.timeScale = timeScale;
        this.live = new LiveRequirements(model, endpoints.busIn(), endpoints.busOut())
                .clock(() -> Math.round(recorder.elapsed() / timeScale)).onEvent(this::tell);
    }

    /** Starts the monitors and waits until they listen (before the engine starts: they see its first decision). */
    static DemoRequirements start(RequirementModel model, Endpoints endpoints, BusRecorder recorder, double timeScale,
            Narrator narrator) throws InterruptedException {
        DemoRequirements r = new DemoRequirements(model, endpoints, recorder, timeScale, narrator);
        r.live.start();
        if (!r.live.awaitSubscribed(10_000)) {
            r.close();
            throw new IllegalStateException("the requirement monitors did not connect to the bus within 10 s");
        }
        return r;
    }

    /** A world ms of the monitors on the console's axis (ms since the recorder started). */
    long axis(long worldMs) {
        return Math.round(worldMs * timeScale);
    }

    private void tell(RequirementEvent e) {
        narrator.say(axis(e.timeMs()), WHO, e.verdict().equals(RequirementEvent.MET) ? e.name() + " met again" : e.describe());
    }

    /** Ends the checks (open windows decided), tells each requirement's verdict over the run; returns them. */
    List<RequirementResult> finish() throws InterruptedException {
        List<RequirementResult> results = live.finish();
        if (results == null) {
            narrator.say(recorder.elapsed(), WHO, "the requirement monitors failed (see the log): no verdicts");
            return List.of();
        }
        for (RequirementResult r : results) {
            narrator.say(recorder.elapsed(), WHO, verdictLine(r));
        }
        return results;
    }

    private String verdictLine(RequirementResult r) {
        return r.name() + ": " + switch (r.verdict()) {
            case VIOLATED -> "violated " + (r.violations() == 1 ? "once" : r.violations() + " times") + " over the run, first at "
                    + TimelineReport.seconds(axis(r.firstViolation().timeMs())) + " s";
            case OPEN -> "no violation, an obligation still open at the end (since "
                    + TimelineReport.seconds(axis(r.openSinceMs())) + " s)";
            case NOT_EVALUATED -> "never evaluated: no value for " + String.join(", ", r.neverValued());
            case HOLDS -> Verdict.HOLDS.text() + " over the run";
        };
    }

    @Override
    public void close() {
        live.close();
    }
}
