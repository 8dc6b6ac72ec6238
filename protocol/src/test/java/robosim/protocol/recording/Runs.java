package robosim.protocol.recording;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import robosim.protocol.Command;
import robosim.protocol.MessageDelivery;
import robosim.protocol.Snapshot;
import robosim.protocol.Snapshot.RobotView;
import robosim.protocol.WorldDescription;
import robosim.protocol.RobotParameters;
import robosim.protocol.SonarUnit;

/**
 * A literal run for the recording tests: a 6000 x 4000 mm world with one wall and two robots;
 * r1 drives along +x at 100 mm a step and stalls at step 5, r2 turns on the spot, speaks at step 2
 * and messages r1 at step 3.
 */
final class Runs {
    static final int STEPS = 10;

    private Runs() {
    }

    static RobotParameters params() {
        return new RobotParameters("Pioneer", "p3dx", 250, 425, 210, 301, 2200, 500, 300, 300, 100, 100,
                0.0056, 5000, List.of(new SonarUnit(0, 69, 136, 90), new SonarUnit(1, 166, 27, 10)));
    }

    static WorldDescription world() {
        return new WorldDescription("literal", 6000, 4000, 100,
                List.of(new WorldDescription.Obstacle(new double[] {3000, 100, 3100, 100, 3100, 3000, 3000, 3000}, 500)),
                List.of(new WorldDescription.RobotInfo("r1", "pioneer", params()),
                        new WorldDescription.RobotInfo("r2", "pioneer", params())),
                List.of(new WorldDescription.HeatSource(5000, 3000, 40)));
    }

    static Snapshot snapshot(int step) {
        boolean stalled = step >= 5;
        double x1 = 1000 + 100 * Math.min(step, 5);
        RobotView r1 = new RobotView("r1", x1, 1000.5, 0, stalled, true, new int[] {5000 - step, 2000 + step},
                x1 + 0.25 * step, 1000.5, 0.1 * step, new int[] {8000, 7000 - step, 6000}, 1, stalled ? 0 : 1000, 0);
        RobotView r2 = new RobotView("r2", 4500, 2000, -180 + 15.5 * step, false, step < 9, new int[] {1234, 4321},
                4500, 2000, -180 + 15.5 * step, new int[0], 1, 0, 155);
        List<MessageDelivery> messages = step == 3
                ? List.of(new MessageDelivery("r2", Command.Addressing.ROBOT, "r1", "text", "over here", 3, 1))
                : List.of();
        List<Snapshot.Said> said = step == 2 ? List.of(new Snapshot.Said("r2", "hello")) : List.of();
        return new Snapshot(step, step * 100L, List.of(r1, r2), messages, said);
    }

    static List<Snapshot> snapshots() {
        List<Snapshot> snapshots = new ArrayList<>();
        for (int step = 0; step <= STEPS; step++) {
            snapshots.add(snapshot(step));
        }
        return snapshots;
    }

    /** @return the bytes of the literal run recorded, with or without sensors, ended or not */
    static byte[] record(boolean sensors, boolean ended) throws IOException {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        try (RecordingWriter w = new RecordingWriter(bytes, "literal.rsr", sensors)) {
            w.world(world());
            for (Snapshot f : snapshots()) {
                w.snapshot(f);
            }
            if (ended) {
                w.end("done: step limit 10 reached");
            }
        }
        return bytes.toByteArray();
    }
}
