package org.miron.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import org.miron.dds.Bridge;
import org.miron.dds.config.BridgeConfig;
import org.miron.dds.config.ConfigException;
import org.miron.dds.config.ConfigReader;
import org.miron.dds.transport.DdsException;
import org.miron.dds.transport.IhmcTransport;
import org.miron.dds.types.DefinitionException;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/** {@code miron dds-bridge --config FILE}: the DDS / ROS 2 bridge (docs/dds.md). */
@Command(name = "dds-bridge", mixinStandardHelpOptions = true,
        description = "Bridge a ROS 2 robot (DDS) and the bus: ROS 2 topics and RoQME's DDS contexts into roqme.context, "
                + "decisions out to ROS 2 topics (transient-local), estimates out as std_msgs/Float64 and RoqmeEstimate "
                + "(or RoqmeEstimate in). The mapping is a JSON file (docs/dds-bridge.schema.json).",
        exitCodeListHeading = ExitCodes.HEADING,
        exitCodeList = { "2:the configuration is refused (file:line:col), DDS cannot start, bad usage", ExitCodes.SIGTERM,
                ExitCodes.SIGINT })
public final class DdsBridgeCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Option(names = "--config", required = true, paramLabel = "FILE", description = "the bridge's mapping (JSON, docs/dds.md)")
    Path config;

    @Option(names = "--status-interval", paramLabel = "MS",
            description = "publish miron.dds.status at least this often (default: ${DEFAULT-VALUE})")
    long statusInterval = 5000;

    @Option(names = "--skill-interface", paramLabel = "ENDPOINT",
            description = "where the bridge answers the engine's change-parameter queries in the skill interface's place, when a "
                    + "decision mapping names a parameter (default: ${DEFAULT-VALUE})")
    String skillInterface = org.miron.runtime.Endpoints.DEFAULT_SKILL;

    @Mixin
    BrokerEndpoints.BusIn busIn = new BrokerEndpoints.BusIn();

    @Mixin
    BrokerEndpoints.BusOut busOut = new BrokerEndpoints.BusOut();

    @Override
    public Integer call() {
        PrintWriter err = spec.commandLine().getErr();
        if (statusInterval <= 0) {
            err.println("miron dds-bridge: error: --status-interval must be positive, got " + statusInterval);
            return 2;
        }
        BridgeConfig c;
        try {
            c = ConfigReader.read(Files.readString(config), config, IhmcTransport.CATALOG, err::println);
        } catch (IOException e) {
            err.println("miron dds-bridge: error: cannot read " + config + ": " + e.getMessage());
            return 2;
        } catch (ConfigException e) {
            err.println(e.format(config.toString()));
            return 2;
        } catch (DefinitionException e) {
            err.println(e.format());
            return 2;
        }
        Bridge bridge;
        try {
            bridge = new Bridge(c, new IhmcTransport(c.domain(), c.name(), c.interfaces(), c.types()), busIn.endpoint, busOut.endpoint,
                    skillInterface, statusInterval).start();
        } catch (DdsException e) {
            err.println("miron dds-bridge: error: " + e.getMessage());
            return 2;
        }
        System.out.println("miron dds-bridge: domain " + c.domain() + " on " + c.interfaces().stream().map(a -> a.getHostAddress()).toList()
                + ", " + c.contexts().size() + " context topics, " + c.decisions().size() + " decision topics, "
                + c.estimates().size() + " estimate topics"
                + (c.types().loaded().isEmpty() ? "" : ", " + c.types().loaded().size() + " message types loaded")
                + (c.answersParameters() ? ", change-parameter answered on " + skillInterface : "") + (c.roqme() == null ? "" : ", RoQME topics in \"" + c.roqme().partition() + "\"")
                + ", bus " + busIn.endpoint + " / " + busOut.endpoint);
        return UntilShutdown.run("dds-bridge", bridge);
    }
}
