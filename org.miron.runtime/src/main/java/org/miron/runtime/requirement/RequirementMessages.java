package org.miron.runtime.requirement;

import com.fasterxml.jackson.databind.node.ObjectNode;
import org.miron.runtime.Json;

/** A requirement event as JSON: the body of {@code miron.requirement}, and what reports and summaries hold. */
public final class RequirementMessages {
    private RequirementMessages() {
    }

    /** {@code {"name","verdict","time","detected","values"}}, times in seconds. */
    public static ObjectNode event(RequirementEvent e) {
        ObjectNode o = Json.object();
        o.put("name", e.name());
        o.put("verdict", e.verdict());
        o.put("time", e.timeMs() / 1000.0);
        o.put("detected", e.detectedMs() / 1000.0);
        o.set("values", Json.MAPPER.valueToTree(e.values()));
        return o;
    }
}
