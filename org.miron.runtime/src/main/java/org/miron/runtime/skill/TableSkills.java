package org.miron.runtime.skill;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import org.miron.runtime.Json;

/** Skills that take their table's time and end with its result, whatever else happens. */
public final class TableSkills implements SkillBehaviour {
    private record Running(long id, long dueMillis, SkillTable.Entry entry) {
    }

    private final SkillTable table;
    private final List<Running> running = new ArrayList<>();
    private Results results;

    public TableSkills(SkillTable table) {
        this.table = table;
    }

    @Override
    public void start(Results sink, long nowMs) {
        this.results = sink;
    }

    @Override
    public void push(long id, JsonNode skill, long nowMs) {
        SkillTable.Entry entry = table.lookup(skill.path("name").asText());
        running.add(new Running(id, nowMs + entry.durationMs(), entry));
    }

    @Override
    public void abortAll(long nowMs) {
        for (Running r : running) {
            results.publish(r.id(), "ABORT", Json.MAPPER.nullNode(), Json.object());
        }
        running.clear();
    }

    @Override
    public long nextDue(long nowMs) {
        long t = Long.MAX_VALUE;
        for (Running r : running) {
            t = Math.min(t, r.dueMillis());
        }
        return t;
    }

    @Override
    public void advance(long nowMs) {
        for (Iterator<Running> it = running.iterator(); it.hasNext();) {
            Running r = it.next();
            if (r.dueMillis() <= nowMs) {
                it.remove();
                results.publish(r.id(), r.entry().result(), r.entry().resultValue(), r.entry().outputs());
            }
        }
    }
}
