package robosim.env.core;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import robosim.protocol.Command;
import robosim.protocol.SonarReading;

class SonarTest {
    @Test
    void frontSonarsMeasureFromTheirTransducerToTheNearestPointInTheirCone() {
        // wall face at x = 3000, robot centre at x = 1000 facing it
        Simulation sim = new Simulation(Worlds.world(10000, 10000, List.of(Worlds.box(3000, 0, 3100, 10000)),
                Worlds.robot("r", 1000, 5000, 0)));
        int[] sonar = sim.state("r").get(SonarReading.PART).ranges();
        // sonars 3 and 4 sit 166 mm ahead at ±10°; their cones (±15°) contain the wall's normal
        assertEquals(2000 - 166, sonar[3]);
        assertEquals(2000 - 166, sonar[4]);
        // sonar 2 at 148 mm, 30°: the cone's nearest edge is at 15°, so (2000 - 148) / cos 15°
        assertEquals(Math.round((2000 - 148) / Math.cos(Math.toRadians(15))), sonar[2]);
        // rear sonars see nothing within 5000 mm except the world has no walls behind: maximum
        assertEquals(5000, sonar[11]);
    }

    @Test
    void echoesNearerThanTheMinimumReadTheMinimum() {
        Simulation sim = new Simulation(Worlds.world(10000, 10000, List.of(Worlds.box(1250, 0, 1350, 10000)),
                Worlds.robot("r", 1000, 5000, 0)));
        assertEquals(100, sim.state("r").get(SonarReading.PART).ranges()[3]);
    }

    @Test
    void rearSonarsSeeAWallShrinkWhileDrivingBackwards() {
        Simulation sim = new Simulation(Worlds.world(10000, 10000, List.of(Worlds.box(0, 0, 100, 10000)),
                Worlds.robot("r", 2000, 5000, 0)));
        int before = sim.state("r").get(SonarReading.PART).ranges()[11];
        sim.step(Map.of("r", List.of(new Command.SetVel(-400))));
        for (int i = 0; i < 20; i++) {
            sim.step(Map.of());
        }
        int after = sim.state("r").get(SonarReading.PART).ranges()[11];
        assertEquals(2000 - 100 - 255, before, 1);
        assertEquals(Math.round(sim.state("r").x() - 100 - 255), after, 1);
    }

    @Test
    void drivingBackwardsIntoAWallStopsAtContactWhileTheRearSonarsSeeItShrink() {
        // the wall's face at x = 100 behind the robot; the p3dx rear is 301 mm behind its centre
        Simulation sim = new Simulation(Worlds.world(10000, 10000, List.of(Worlds.box(0, 0, 100, 10000)),
                Worlds.robot("r", 2500, 5000, 0)));
        sim.step(Map.of("r", List.of(new Command.Move(-5000))));
        int previous = Integer.MAX_VALUE;
        int shrinking = 0;
        for (int i = 0; i < 200 && !sim.state("r").stalled(); i++) {
            int rear = Math.min(sim.state("r").get(SonarReading.PART).ranges()[11], sim.state("r").get(SonarReading.PART).ranges()[12]);
            assertTrue(rear <= previous, "rear sonars never see the wall recede while backing: " + rear + " after " + previous);
            shrinking += rear < previous ? 1 : 0;
            previous = rear;
            sim.step(Map.of());
        }
        var s = sim.state("r");
        assertTrue(s.stalled(), "stopped by the wall");
        assertEquals(100 + 301, s.x(), 0.5, "rear at the wall's face, not inside");
        assertEquals(0, s.th(), 1e-9, "it backed straight, without turning round");
        assertFalse(sim.overlapsAnything("r"));
        assertTrue(shrinking > 10, "the rear readings shrank step after step: " + shrinking);
        assertEquals(100, s.get(SonarReading.PART).ranges()[11], "at the wall the rear sonar reads its minimum");
    }

    @Test
    void sonarsSwitchedOffSendNoReadings() {
        Simulation sim = new Simulation(Worlds.world(10000, 10000, List.of(), Worlds.robot("r", 1000, 5000, 0)));
        sim.step(Map.of("r", List.of(new Command.SetSonar(false))));
        assertEquals(0, sim.state("r").get(SonarReading.PART).ranges().length);
        sim.step(Map.of("r", List.of(new Command.SetSonar(true))));
        assertEquals(16, sim.state("r").get(SonarReading.PART).ranges().length);
    }

    @Test
    void theSameCommandsGiveTheSameTrajectory() {
        int[][] a = trajectory();
        int[][] b = trajectory();
        for (int i = 0; i < a.length; i++) {
            assertArrayEquals(a[i], b[i], "step " + i);
        }
    }

    private static int[][] trajectory() {
        Simulation sim = new Simulation(Worlds.world(6000, 6000, List.of(Worlds.box(2500, 2500, 3500, 3500)),
                Worlds.robot("a", 1000, 1000, 30), Worlds.robot("b", 5000, 5000, -150)));
        int[][] out = new int[200][];
        for (int i = 0; i < 200; i++) {
            Map<String, List<Command>> cmds = i % 40 == 0
                    ? Map.of("a", List.of(new Command.SetVel(400), new Command.SetRotVel(i % 80 == 0 ? 10 : -10)),
                    "b", List.of(new Command.Move(800)))
                    : Map.of();
            sim.step(cmds);
            var s = sim.state("a");
            var t = sim.state("b");
            out[i] = new int[] {(int) Math.round(s.x() * 1000), (int) Math.round(s.y() * 1000),
                    (int) Math.round(t.x() * 1000), (int) Math.round(t.y() * 1000), s.get(SonarReading.PART).ranges()[3], t.get(SonarReading.PART).ranges()[4]};
        }
        return out;
    }
}
