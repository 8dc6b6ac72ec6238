package robosim.env.net;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import robosim.env.core.Simulation;
import robosim.env.world.xml.WorldReader;
import robosim.protocol.Bye;
import robosim.protocol.Command;
import robosim.protocol.Message;
import robosim.protocol.RobotHello;
import robosim.protocol.RobotParameters;
import robosim.protocol.RobotRequests;
import robosim.protocol.Welcome;

/**
 * Robots that join a run under way, over real loopback connections to {@code empty-room.xml}'s r1
 * and r2: late, back after they went, and refused when they bring another body.
 */
@Timeout(value = 30, unit = TimeUnit.SECONDS)
class JoinsTest {
    private Loopback loopback;
    private LogLines log;
    private Simulation sim;
    private SessionRules rules;

    @BeforeEach
    void open() throws IOException {
        loopback = new Loopback();
        log = new LogLines();
        Path p = Path.of(System.getProperty("robosim.root", "")).toAbsolutePath();
        while (!Files.isDirectory(p.resolve("testLoadFiles"))) {
            p = p.getParent();
        }
        sim = new Simulation(WorldReader.read(p.resolve("testLoadFiles/environment/empty-room.xml")));
        rules = new SessionRules(sim);
    }

    @AfterEach
    void close() throws IOException {
        log.close();
        loopback.close();
    }

    private RobotParameters worldParameters() {
        return sim.world().robots().get(0).parameters();
    }

    private void deliver(Peer peer) throws IOException {
        List<Message> got = loopback.receive(peer.connection);
        if (got == null) {
            rules.closed(peer.connection, SessionRules.DISCONNECTED);
            return;
        }
        for (Message m : got) {
            rules.received(peer.connection, m);
        }
    }

    private Peer connect(String name, RobotParameters p) throws IOException {
        Peer peer = loopback.connect(Connection.Kind.ROBOT);
        peer.send(new RobotHello(name, "pioneer", p));
        deliver(peer);
        return peer;
    }

    /** Runs steps 1 to {@code last}, r1 driving forward at 300 mm/s, as the step loop would. */
    private void runSteps(Peer r1, int last) throws IOException {
        for (long k = sim.stepCount() + 1; k <= last; k++) {
            rules.openStep(k);
            r1.send(new RobotRequests(k, k == 1 ? List.of(new Command.SetMotors(true), new Command.SetVel(300)) : List.of()));
            deliver(r1);
            sim.step(rules.closeStep());
        }
    }

    @Test
    void theWelcomeCarriesTheWorldsPropertiesAndTheRunsSeed() throws IOException {
        sim = new Simulation(sim.world().withProperties(Map.of("cellSize", "1500")), 31_337);
        rules = new SessionRules(sim);

        Welcome w = assertInstanceOf(Welcome.class, connect("r1", worldParameters()).read());

        assertEquals(Map.of("cellSize", "1500"), w.properties());
        assertEquals(31_337, w.seed());
    }

    @Test
    void aRobotThatConnectsWhileAStepIsOpenIsWelcomedAndAwaitedFromTheNextStep() throws IOException {
        Peer r1 = connect("r1", worldParameters());
        rules.start();
        runSteps(r1, 2);
        rules.openStep(3);

        Peer r2 = connect("r2", worldParameters());

        Welcome w = assertInstanceOf(Welcome.class, r2.read());
        assertEquals(List.of(2L, 4500.0, 4500.0, -135.0), List.of(w.state().step(), w.state().x(), w.state().y(),
                w.state().th()));
        assertEquals(Set.of("r1"), rules.waitingFor());
        r1.send(new RobotRequests(3, List.of()));
        deliver(r1);
        sim.step(rules.closeStep());
        rules.openStep(4);
        assertEquals(Set.of("r1", "r2"), rules.waitingFor());
        assertEquals(List.of(new Join("r2", Join.Kind.LATE, 4)), rules.joins());
        assertTrue(log.infos().contains("robot r2 joined late at step 4 (after step 2)"), log.infos().toString());
    }

    @Test
    void aRobotThatComesBackResumesItsBodyAndOdometryWhereItStopped() throws IOException {
        Peer r1 = connect("r1", worldParameters());
        Peer r2 = connect("r2", worldParameters());
        rules.start();
        for (long k = 1; k <= 5; k++) {
            rules.openStep(k);
            r1.send(new RobotRequests(k, List.of()));
            r2.send(new RobotRequests(k, k == 1 ? List.of(new Command.SetMotors(true), new Command.SetVel(300)) : List.of()));
            deliver(r1);
            deliver(r2);
            sim.step(rules.closeStep());
        }
        rules.openStep(6);
        r2.send(new Bye("going away"));
        deliver(r2);
        r1.send(new RobotRequests(6, List.of()));
        deliver(r1);
        sim.step(rules.closeStep());
        double stoppedAt = sim.summary("r2").x();
        double odometryAt = sim.summary("r2").odoX();

        Peer back = connect("r2", worldParameters());

        Welcome w = assertInstanceOf(Welcome.class, back.read());
        assertTrue(sim.summary("r2").distance() > 20, "it had moved: " + sim.summary("r2").distance());
        assertEquals(stoppedAt, sim.summary("r2").x(), 1e-9);
        assertEquals(odometryAt, w.state().x(), 1e-9);
        assertEquals(List.of(new Join("r2", Join.Kind.REJOINED, 7)), rules.joins());
        assertEquals(List.of(new Departure("r2", Departure.Kind.LEFT, 6, "going away")), rules.departures());
    }

    @Test
    void aRobotThatComesBackWithAnotherBodyIsRefusedNamingTheDifference() throws IOException {
        Peer r1 = connect("r1", worldParameters());
        rules.start();
        runSteps(r1, 1);
        RobotParameters p = worldParameters();
        RobotParameters faster = new RobotParameters(p.robotClass(), p.subclass(), p.robotRadius(), p.robotWidth(),
                p.robotLengthFront(), p.robotLengthRear(), 1234, p.maxRVelocity(), p.transAccel(), p.transDecel(),
                p.rotAccel(), p.rotDecel(), p.diffConvFactor(), p.sonarMaxRange(), p.sonarUnits(), p.laserX(),
                p.laserY(), p.laserTh(), p.laserMaxRange(), p.shape());

        Peer r2 = connect("r2", faster);

        Bye bye = assertInstanceOf(Bye.class, r2.read());
        assertEquals("refused: robot r2 joins the run under way (after step 1) with parameters that differ from its"
                + " body's (first: maxVelocity " + p.maxVelocity() + " in its body, 1234.0 in the program's); a body"
                + " keeps its parameters during a run", bye.reason());
        assertEquals(Set.of("r1"), rules.connectedRobots().keySet());
    }

    @Test
    void aRobotRemovedBeforeStepOneIsInTheDepartures() throws IOException {
        connect("r1", worldParameters());
        connect("r2", worldParameters());
        rules.start();

        rules.drop("r2", "removed by control client c after step 0");

        assertEquals(List.of(new Departure("r2", Departure.Kind.DROPPED, 0, "removed by control client c after step 0")),
                rules.departures());
    }

    /** @return the report of a run of 9 steps without robots, timings or a find, but these comings and goings */
    private static RunReport report(List<Departure> departures, List<Join> joins) {
        return new RunReport(9, 900, "step limit 9 reached", RunEnding.STEP_LIMIT, List.of(), 0, null, 0, departures,
                joins, List.of(), Map.of(), null);
    }

    @Test
    void aRobotThatCameBackRanToTheEndInTheReport() {
        RunReport report = report(List.of(new Departure("r2", Departure.Kind.LOST, 4, "gone")),
                List.of(new Join("r2", Join.Kind.REJOINED, 5)));

        assertEquals(Optional.empty(), report.departure("r2"));
        assertEquals(List.of(new Join("r2", Join.Kind.REJOINED, 5)), report.joinsOf("r2"));
    }

    @Test
    void aRobotThatWentAgainAfterComingBackIsReportedGone() {
        Departure second = new Departure("r2", Departure.Kind.LEFT, 5, "again");
        RunReport report = report(List.of(new Departure("r2", Departure.Kind.LOST, 4, "gone"), second),
                List.of(new Join("r2", Join.Kind.REJOINED, 5)));

        assertEquals(Optional.of(second), report.departure("r2"));
    }

    @Test
    void joinsBeforeTheRunStartsAreNotRecorded() throws IOException {
        Peer r1 = connect("r1", worldParameters());
        r1.send(new Bye("changed my mind"));
        deliver(r1);
        connect("r1", worldParameters());

        assertEquals(List.of(), rules.joins());
        assertEquals(List.of(), rules.departures());
        assertEquals(Set.of("r1"), rules.connectedRobots().keySet());
    }
}
