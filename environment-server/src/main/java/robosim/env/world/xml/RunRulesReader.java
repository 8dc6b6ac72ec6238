package robosim.env.world.xml;

import java.util.ArrayList;
import java.util.List;
import robosim.env.world.Bounds;
import robosim.env.world.EndRule;
import robosim.env.world.HeatSource;
import robosim.env.world.RunRules;
import robosim.geometry.Pose2D;

/**
 * Reads a world's {@code open} and {@code motors} attributes, its {@code <spawn>} poses and its
 * {@code <end>} into {@link RunRules}, naming the line of the element that breaks a rule. A spawn pose must lie inside
 * the world; whether a body fits there is decided when a robot joins (its body comes with it).
 */
final class RunRulesReader {
    /** The most spawn poses a world may have. */
    static final int MAX_SPAWNS = 10_000;

    private RunRulesReader() {
    }

    /**
     * @param attributes the file's attribute reader
     * @param root       the world element
     * @param bounds     the world's extent
     * @param gold       the world's gold, or null
     * @return the rules
     */
    static RunRules read(Attributes attributes, WorldElement root, Bounds bounds, HeatSource gold) {
        boolean open = attributes.bool(root, "open", root.open, false);
        EndElement end = null;
        List<Pose2D> spawns = new ArrayList<>();
        for (Element child : root.children) {
            if (child instanceof EndElement e) {
                if (end != null) {
                    throw attributes.error(e, "a world has at most one <end>; the first is at line " + end.line());
                }
                end = e;
            } else if (child instanceof SpawnElement s) {
                if (spawns.size() == MAX_SPAWNS) {
                    throw attributes.error(s, "a world has at most " + MAX_SPAWNS + " <spawn> elements");
                }
                spawns.add(spawn(attributes, s, bounds));
            }
        }
        return new RunRules(end == null ? EndRule.DEFAULT : end(attributes, end, gold), open, spawns,
                motors(attributes, root));
    }

    /** {@code motors="enabled"} or {@code "disabled"}, the default: the motors as a Pioneer's program connects. */
    private static boolean motors(Attributes attributes, WorldElement root) {
        if (root.motors == null) {
            return false;
        }
        String word = root.motors.trim();
        if (!word.equals("enabled") && !word.equals("disabled")) {
            throw attributes.error(root, "attribute motors on <world> is " + Attributes.quote(word)
                    + " but must be enabled or disabled (the motors as a Pioneer's program connects)");
        }
        return word.equals("enabled");
    }

    private static Pose2D spawn(Attributes attributes, SpawnElement s, Bounds bounds) {
        double x = attributes.number(s, "x", s.x);
        double y = attributes.number(s, "y", s.y);
        double th = attributes.number(s, "th", s.th, 0);
        if (!bounds.contains(x, y)) {
            throw attributes.error(s, "spawn pose at (" + Attributes.format(x) + ", " + Attributes.format(y)
                    + ") is outside the world " + bounds.describe());
        }
        return new Pose2D(x, y, Math.toRadians(th));
    }

    private static EndRule end(Attributes attributes, EndElement e, HeatSource gold) {
        String word = attributes.text(e, "when", e.when);
        EndRule.When when = null;
        for (EndRule.When w : EndRule.When.values()) {
            if (w != EndRule.When.DEFAULT && w.word().equals(word)) {
                when = w;
            }
        }
        if (when == null) {
            throw attributes.error(e, "attribute when on <end> is " + Attributes.quote(word)
                    + "; it is one of all-left, any-left, steps, gold");
        }
        if (when == EndRule.When.STEPS && e.steps == null) {
            throw attributes.error(e, "missing required attribute steps on <end when=\"steps\">");
        }
        long steps = e.steps == null ? 0 : attributes.wholeNumber(e, "steps", e.steps, 0, 1);
        if (when == EndRule.When.GOLD && gold == null) {
            throw attributes.error(e, "<end when=\"gold\"> in a world without <gold>: the run could not end so");
        }
        return new EndRule(when, steps);
    }
}
