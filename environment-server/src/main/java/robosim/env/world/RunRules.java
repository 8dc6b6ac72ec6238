package robosim.env.world;

import java.util.List;
import robosim.geometry.Pose2D;

/**
 * Who may join a world's run and when it ends, from the world file's {@code <world open=...>},
 * {@code <spawn>} and {@code <end>}; and whether a Pioneer's motors are enabled when its program
 * connects, from {@code <world motors=...>}.
 *
 * @param end    when the run ends of itself
 * @param open   whether robots the world does not name may join, at the spawn poses
 * @param spawns where robots the world does not name are placed, x and y in mm, th in radians, in
 *               file order: each newcomer at the first one no body overlaps
 * @param motorsEnabled whether a Pioneer's motors are enabled when its program connects: false (the
 *               default) as on a real robot, whose program calls {@code enableMotors()}
 */
public record RunRules(EndRule end, boolean open, List<Pose2D> spawns, boolean motorsEnabled) {
    /** A closed world without spawn poses that ends as it always did ({@link EndRule#DEFAULT}). */
    public static final RunRules DEFAULT = new RunRules(EndRule.DEFAULT, false, List.of());

    /** Copies the list so the record stays immutable. */
    public RunRules {
        if (end == null) {
            throw new IllegalArgumentException("null was supplied for end: use EndRule.DEFAULT");
        }
        spawns = List.copyOf(spawns);
    }

    /**
     * @param isOpen whether robots the world does not name may join
     * @return the same rules, open or closed
     */
    public RunRules withOpen(boolean isOpen) {
        return new RunRules(end, isOpen, spawns, motorsEnabled);
    }

    /**
     * Rules whose Pioneers connect with their motors disabled.
     *
     * @param end    when the run ends of itself
     * @param open   whether robots the world does not name may join
     * @param spawns where robots the world does not name are placed
     */
    public RunRules(EndRule end, boolean open, List<Pose2D> spawns) {
        this(end, open, spawns, false);
    }

    /**
     * @param enabled whether a Pioneer's motors are enabled when its program connects
     * @return the same rules with that start for the motors
     */
    public RunRules withMotorsEnabled(boolean enabled) {
        return new RunRules(end, open, spawns, enabled);
    }
}
