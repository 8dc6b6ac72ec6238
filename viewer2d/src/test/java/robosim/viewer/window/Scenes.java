package robosim.viewer.window;

import java.lang.reflect.InvocationTargetException;
import java.util.List;
import java.util.concurrent.Callable;
import javax.swing.SwingUtilities;
import robosim.protocol.Snapshot;
import robosim.protocol.Snapshot.RobotView;
import robosim.protocol.WorldDescription;
import robosim.protocol.WorldDescription.Obstacle;
import robosim.protocol.WorldDescription.RobotInfo;
import robosim.protocol.RobotParameters;
import robosim.protocol.SonarUnit;

/**
 * A literal world for the window tests, 4000 x 2000 mm with a 500 mm square block from (1000, 500)
 * to (1500, 1000) and robot r1, 400 x 380 mm; and a way to run code on the Swing event thread.
 */
final class Scenes {
    private Scenes() {
    }

    static WorldDescription world() {
        RobotParameters body = new RobotParameters("Pioneer", "test", 250, 380, 200, 200, 1000, 300, 300, 300,
                100, 100, 0.006, 5000, List.of(new SonarUnit(0, 200, 0, 0), new SonarUnit(1, 0, 190, 90)));
        return new WorldDescription("fixture", 4000, 2000, 100,
                List.of(new Obstacle(new double[] {1000, 500, 1500, 500, 1500, 1000, 1000, 1000}, 500)),
                List.of(new RobotInfo("r1", "pioneer", body)));
    }

    /** r1 at x = 2000 + 100 * step, y = 1500, heading 0, with sonar readings. */
    static Snapshot snapshot(int step) {
        return new Snapshot(step, step * 100L, List.of(
                new RobotView("r1", 2000 + 100 * step, 1500, 0, false, true, new int[] {800, 400})));
    }

    /** Runs code on the Swing event thread and returns its result. */
    static <T> T onEdt(Callable<T> code) throws Exception {
        Object[] result = new Object[1];
        try {
            SwingUtilities.invokeAndWait(() -> {
                try {
                    result[0] = code.call();
                } catch (Exception e) {
                    throw new IllegalStateException(e);
                }
            });
        } catch (InvocationTargetException e) {
            throw new AssertionError(e.getCause());
        }
        @SuppressWarnings("unchecked")
        T t = (T) result[0];
        return t;
    }
}
