package robosim.protocol;

/**
 * The ground-truth sensor's part of a robot's state, while it is on ({@link Command.ReportTruePose}):
 * the robot's true pose, as a simulator's SIMSTAT reports it.
 *
 * @param x  mm, world frame
 * @param y  mm, world frame
 * @param th degrees
 */
public record TruePose(double x, double y, double th) {
    /** Its key: absent reads as null. */
    public static final StatePart<TruePose> PART = StatePart.of("truePose", TruePose.class);
}
