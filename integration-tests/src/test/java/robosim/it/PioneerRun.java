package robosim.it;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import robosim.env.net.ServerOptions;
import robosim.env.world.RobotSpec;
import robosim.env.world.World;
import robosim.env.world.xml.WorldReader;
import robosim.hw.HardwareOptions;
import robosim.params.RobotParameterFiles;
import robosim.pioneer.PioneerClient;
import robosim.pioneer.server.PioneerPortOptions;
import robosim.pioneer.server.PioneerPorts;
import robosim.pioneer.server.ServedRobot;

/**
 * An Environment in this JVM with Pioneer ports for its robots, on loopback and free ports, paced in
 * real time while a client is attached, as {@code env --pioneer-port} runs them. Closing it closes
 * the ports and the Environment.
 */
final class PioneerRun implements AutoCloseable {
    final LocalEnvironment env;
    final PioneerPorts ports;

    /**
     * @param world        the world
     * @param allowSimExit whether SIM_EXIT may end the run
     * @param simExit      what an allowed SIM_EXIT does
     */
    PioneerRun(World world, boolean allowSimExit, java.util.function.IntConsumer simExit) throws Exception {
        this(world, 0, allowSimExit, simExit);
    }

    /**
     * @param world        the world
     * @param maxSteps     the run's length, 0 for no limit
     * @param allowSimExit whether SIM_EXIT may end the run
     * @param simExit      what an allowed SIM_EXIT does
     */
    PioneerRun(World world, long maxSteps, boolean allowSimExit, java.util.function.IntConsumer simExit)
            throws Exception {
        env = new LocalEnvironment(world, 1, ServerOptions.loopback().withMaxSteps(maxSteps));
        List<ServedRobot> robots = new ArrayList<>();
        for (RobotSpec r : world.robots()) {
            robots.add(new ServedRobot(r.name(), r.type(), r.parameters(),
                    RobotParameterFiles.conversionFactors(r.parameterFile().toString()), world.stepMs()));
        }
        PioneerPorts opened = null;
        try {
            opened = PioneerPorts.open(robots, new PioneerPortOptions("127.0.0.1", 0, allowSimExit,
                    PioneerPortOptions.DEFAULT_WATCHDOG_MS, true, HardwareOptions.defaults()), "127.0.0.1",
                    env.robotPort(), null, simExit);
        } finally {
            if (opened == null) {
                env.close();
            }
        }
        ports = opened;
    }

    /** A room of 10 × 10 m with one p3dx, r1, at (3000, 3000) facing +x. */
    static World room(Path dir) throws Exception {
        Path world = dir.resolve("room.xml");
        Files.writeString(world, """
                <world name="room" width="10000" height="10000" boundary="true">
                  <robot name="r1" type="pioneer" x="3000" y="3000" th="0" params="%s"/>
                </world>
                """.formatted(LocalEnvironment.root().resolve("testLoadFiles/robots/p3dx.p")));
        return WorldReader.read(world);
    }

    /** The room with a second p3dx, r2, at (3000, 6000) facing +x. */
    static World roomForTwo(Path dir) throws Exception {
        Path world = dir.resolve("room2.xml");
        String params = LocalEnvironment.root().resolve("testLoadFiles/robots/p3dx.p").toString();
        Files.writeString(world, """
                <world name="room" width="10000" height="10000" boundary="true">
                  <robot name="r1" type="pioneer" x="3000" y="3000" th="0" params="%s"/>
                  <robot name="r2" type="pioneer" x="3000" y="6000" th="0" params="%s"/>
                </world>
                """.formatted(params, params));
        return WorldReader.read(world);
    }

    /**
     * Connects an ARIA-style client to a robot's port and opens it.
     *
     * @param robot the robot
     * @return the client, handshake done, OPEN sent, and sending a PULSE whenever it has been silent for
     *         500 ms, as ARIA does
     */
    PioneerClient client(String robot) throws Exception {
        PioneerClient c = PioneerClient.connect("127.0.0.1", ports.portOf(robot), 10_000);
        c.open(10_000);
        c.startPulses();
        return c;
    }

    @Override
    public void close() throws Exception {
        try {
            ports.close();
        } finally {
            env.close();
        }
    }
}
