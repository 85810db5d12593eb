package org.miron.cli;

import java.io.IOException;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import org.miron.runtime.Endpoints;
import org.miron.runtime.skill.SkillInterfaceMock;
import org.miron.runtime.skill.SkillTable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/** {@code miron skill-mock}: the SmartSoft ComponentSkillInterface stand-in. */
@Command(name = "skill-mock", mixinStandardHelpOptions = true,
        description = "Run the mock SmartSoft skill interface (REP queries, PUB skill results).",
        exitCodeListHeading = ExitCodes.HEADING,
        exitCodeList = { ExitCodes.STARTUP, ExitCodes.SIGTERM, ExitCodes.SIGINT })
public final class SkillMockCommand implements Callable<Integer> {
    @Option(names = "--rep", description = "REP endpoint for queries (default: ${DEFAULT-VALUE})")
    String rep = Endpoints.DEFAULT_SKILL;

    @Option(names = "--pub", description = "PUB endpoint for skill results (default: ${DEFAULT-VALUE})")
    String pub = Endpoints.DEFAULT_SKILL_EVENTS;

    @Option(names = "--skills", paramLabel = "FILE",
            description = "skill table JSON: {\"GoTo\": {\"duration\": 1500, \"result\": \"SUCCESS\"}, \"*\": {...}}")
    Path skills;

    @Override
    public Integer call() {
        SkillTable table;
        try {
            table = skills == null ? SkillTable.defaults() : SkillTable.load(skills);
        } catch (IOException e) {
            System.err.println("miron skill-mock: error: cannot read skill table: " + e.getMessage());
            return 2;
        }
        SkillInterfaceMock mock;
        try {
            mock = new SkillInterfaceMock(rep, pub, table).start();
        } catch (IllegalStateException e) {
            System.err.println("miron skill-mock: error: " + e.getMessage());
            return 2;
        }
        return UntilShutdown.run("skill-mock", mock);
    }
}
