package robosim.it;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import robosim.aria.ArRobot;
import robosim.env.core.RobotSummary;
import robosim.env.net.Departure;
import robosim.env.net.RunReport;
import robosim.examples.meetup.MeetUp;

/** Two robots talking over comms ({@code examples/meet-up}): they tell each other where they are and meet. */
@Timeout(value = 2, unit = TimeUnit.MINUTES)
class MeetUpExampleTest {
    @Test
    void theTwoRobotsOfTheEmptyRoomMeetByTheirMessagesAndLeave() throws Exception {
        try (ThreadedRun run = new ThreadedRun(LocalEnvironment.root().resolve("testLoadFiles/environment/empty-room.xml"), 1, 600)) {
            Future<Integer> r1 = run.robot(() -> meetUp("r1", "r2", run.port()));
            Future<Integer> r2 = run.robot(() -> meetUp("r2", "r1", run.port()));
            int heard1 = r1.get(90, TimeUnit.SECONDS);
            int heard2 = r2.get(90, TimeUnit.SECONDS);
            RunReport report = run.await();
            assertEquals("every robot has disconnected", report.endReason(), "they met before the step limit");
            assertTrue(heard1 >= 3 && heard2 >= 3, "each heard the other several times: " + heard1 + ", " + heard2);
            RobotSummary a = report.robots().get(0);
            RobotSummary b = report.robots().get(1);
            double apart = Math.hypot(a.x() - b.x(), a.y() - b.y());
            assertTrue(apart < MeetUp.NEAR + 200 && apart > 500, "they stand near each other: " + apart + " mm");
            for (RobotSummary r : report.robots()) {
                assertEquals(0, r.collisions(), r.name());
                assertTrue(r.distance() > 800, r.name() + " drove towards the other: " + r.distance());
                assertEquals(Departure.Kind.LEFT, report.departure(r.name()).orElseThrow().kind(), r.name());
            }
        }
    }

    private static int meetUp(String name, String peer, int port) {
        ArRobot robot = new ArRobot(name, "127.0.0.1", port, "p3dx");
        assertTrue(robot.blockingConnect(), robot.getConnectionError());
        robot.enableMotors();
        int heard = new MeetUp(robot, peer).run();
        robot.disconnect();
        return heard;
    }
}
