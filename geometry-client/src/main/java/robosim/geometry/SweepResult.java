package robosim.geometry;

/**
 * How far a body could follow a motion before touching something.
 *
 * @param fraction the part of the motion that is free, 0 to 1
 * @param pose     the pose reached
 * @param blocked  whether something stopped the motion before its end
 */
public record SweepResult(double fraction, Pose2D pose, boolean blocked) {
}
