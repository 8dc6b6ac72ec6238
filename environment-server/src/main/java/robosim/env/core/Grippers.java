package robosim.env.core;

import java.util.HashMap;
import java.util.List;
import java.util.Map;
import robosim.geometry.BodyShape;
import robosim.geometry.GeometryClient;
import robosim.protocol.Command;
import robosim.protocol.GripperState;

/**
 * The grippers of the robots whose parameters give them one ({@code HasGripper}), and what they
 * do to the world's {@link Pucks}.
 *
 * <p>The gripper sits at the front of the body; its paddles reach {@value #PADDLE_LENGTH} mm ahead
 * of it, {@link GripperModel#OPEN_WIDTH} mm apart when open. A puck lying on the floor whose centre
 * is between the paddles (ahead of the body, within their length and their gap) can be held when
 * the lift is at the bottom: the paddles close on it and centre it. The break beams cross the
 * paddles {@value #INNER_BEAM} mm (inner) and {@value #OUTER_BEAM} mm (outer) ahead of the body; a
 * puck between the paddles breaks a beam its circle crosses (a puck on the floor only while the
 * lift is at the bottom). A held puck moves with the robot, lifted or not, and is put down where
 * it is when the paddles open. While it holds a puck a rectangular robot's body reaches over it,
 * so that the puck cannot pass through walls.
 */
final class Grippers {
    /** How far the paddles reach ahead of the body, mm. */
    static final double PADDLE_LENGTH = 180;
    /** Where the inner break beam crosses the paddles, mm ahead of the body. */
    static final double INNER_BEAM = 30;
    /** Where the outer break beam crosses the paddles, mm ahead of the body. */
    static final double OUTER_BEAM = 150;
    /** The gap kept between the body and a held puck, mm. */
    static final double HOLD_GAP = 1;

    private final Pucks pucks;
    private final GeometryClient geometry;
    private final Map<String, GripperModel> models = new HashMap<>();
    /** How far ahead of its holder's centre each held puck is, mm. */
    private final Map<String, Double> heldAt = new HashMap<>();

    Grippers(Pucks pucks, GeometryClient geometry) {
        this.pucks = pucks;
        this.geometry = geometry;
    }

    /** @return the robot's gripper, or null when its parameters give it none (states may be built in parallel) */
    private synchronized GripperModel model(SimRobot r) {
        return r.params.hasGripper() ? models.computeIfAbsent(r.name, n -> new GripperModel()) : null;
    }

    /**
     * @return the robot's gripper as it is, without making one (readers of the state do not change
     *         the simulation): one not used yet is as it starts; null when the robot has none
     */
    private GripperModel current(SimRobot r) {
        if (!r.params.hasGripper()) {
            return null;
        }
        GripperModel m = models.get(r.name);
        return m != null ? m : new GripperModel();
    }

    /**
     * Hands a gripper command to the robot's gripper.
     *
     * @return why it cannot be carried out (the robot has no gripper), or null
     */
    String command(SimRobot r, Command.Accessory c, long step) {
        Command.Gripper g = (Command.Gripper) c;
        GripperModel m = model(r);
        if (m == null) {
            return "robot " + r.name + " has no gripper (its parameters say HasGripper false): gripper command "
                    + g.op() + " at step " + step + " is ignored";
        }
        m.command(g);
        return null;
    }

    /** Moves every gripper on by one step, after the robots have moved, and carries the pucks held. */
    void step(List<SimRobot> order, double dt) {
        for (SimRobot r : order) {
            GripperModel m = model(r);
            if (m == null) {
                continue;
            }
            int held = pucks.heldBy(r.name);
            int candidate = held < 0 && m.down() ? candidate(r, m) : -1;
            switch (m.advance(dt, candidate < 0 ? 0 : pucks.radius(candidate))) {
                case GRIPPED -> hold(r, candidate);
                case RELEASED -> release(r, held);
                case NONE -> { }
            }
            carry(r);
        }
    }

    /** Moves the puck a robot holds to where its gripper is now. */
    private void carry(SimRobot r) {
        int held = pucks.heldBy(r.name);
        if (held >= 0) {
            double ahead = heldAt.get(r.name);
            double th = Math.toRadians(r.th());
            pucks.carry(geometry, held, r.x() + ahead * Math.cos(th), r.y() + ahead * Math.sin(th));
        }
    }

    private void hold(SimRobot r, int i) {
        double front = r.params.robotLengthFront();
        double ahead = Math.max(local(r, i)[0], front + pucks.radius(i) + HOLD_GAP);
        pucks.hold(geometry, i, r.name);
        heldAt.put(r.name, ahead);
        if (!r.params.isRound()) {
            BodyShape longer = BodyShape.rectangle(ahead + pucks.radius(i), r.params.robotLengthRear(),
                    r.params.robotWidth());
            if (!geometry.overlaps(longer, r.pose(), r.bodyId)) {
                geometry.replaceBody(r.bodyId, longer);
            }
        }
        carry(r);
    }

    private void release(SimRobot r, int i) {
        geometry.replaceBody(r.bodyId, r.body);
        heldAt.remove(r.name);
        pucks.release(geometry, i);
    }

    /** @return the puck on the floor nearest the body whose centre is between the open paddles, or -1 */
    private int candidate(SimRobot r, GripperModel m) {
        double front = r.params.robotLengthFront();
        int best = -1;
        double bestX = Double.POSITIVE_INFINITY;
        for (int i = 0; i < pucks.count(); i++) {
            if (pucks.holder(i) != null) {
                continue;
            }
            double[] l = local(r, i);
            if (l[0] >= front && l[0] <= front + PADDLE_LENGTH && Math.abs(l[1]) < m.gap() / 2
                    && 2 * pucks.radius(i) <= m.gap() && l[0] < bestX) {
                best = i;
                bestX = l[0];
            }
        }
        return best;
    }

    /** @return puck {@code i}'s centre in the robot's frame: mm ahead, mm to the left */
    private double[] local(SimRobot r, int i) {
        double th = Math.toRadians(r.th());
        double dx = pucks.x(i) - r.x();
        double dy = pucks.y(i) - r.y();
        return new double[] {dx * Math.cos(th) + dy * Math.sin(th), -dx * Math.sin(th) + dy * Math.cos(th)};
    }

    /** @return the break beams a puck breaks now, as ARIA's bits */
    private int beams(SimRobot r, GripperModel m) {
        double front = r.params.robotLengthFront();
        int bits = 0;
        for (int i = 0; i < pucks.count(); i++) {
            boolean mine = r.name.equals(pucks.holder(i));
            if (!mine && (pucks.holder(i) != null || !m.down())) {
                continue;
            }
            double[] l = local(r, i);
            double radius = pucks.radius(i);
            if (mine || Math.abs(l[1]) < m.gap() / 2 && l[0] >= front - radius && l[0] <= front + PADDLE_LENGTH) {
                if (Math.abs(l[0] - front - INNER_BEAM) < radius) {
                    bits |= GripperState.INNER_BEAM;
                }
                if (Math.abs(l[0] - front - OUTER_BEAM) < radius) {
                    bits |= GripperState.OUTER_BEAM;
                }
            }
        }
        return bits;
    }

    /** @return the robot's gripper as its switches report it, or null when it has none */
    GripperState state(SimRobot r) {
        GripperModel m = current(r);
        return m == null ? null : m.state(beams(r, m), pucks.heldBy(r.name));
    }

    /** @return whether the robot holds something off the floor */
    synchronized boolean lifted(String robot) {
        GripperModel m = models.get(robot);
        return m != null && !m.down();
    }
}
