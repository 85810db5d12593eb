package org.miron.runtime.skill;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.List;

/**
 * One change-parameter query as the mock applied it: SmartSoft-style commands, the tag
 * {@code UPPER(repo).UPPER(set).UPPER(param)} with its values, then {@code COMMIT}.
 *
 * @param id       query id
 * @param values   the query's {@code values} object, numbers untouched
 * @param commands what SmartSoft would execute, e.g. {@code [COMMNAVIGATIONOBJECTS.CDLPARAMETER.TRANSVEL 83.0 83.0, COMMIT]}
 */
public record ParameterChange(long id, String component, String repository, String set, String parameter,
        String tag, JsonNode values, List<String> commands, long time) {

    /** First value ({@code values["1"]}), the one MIRoN decides. */
    public double value() {
        return values.path("1").asDouble(Double.NaN);
    }
}
