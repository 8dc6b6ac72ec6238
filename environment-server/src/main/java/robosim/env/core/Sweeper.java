package robosim.env.core;

import robosim.geometry.GeometryClient;
import robosim.geometry.SweepResult;

/** How a robot's motion of one step is swept through the world. */
interface Sweeper {
    /** The plain sweep: whatever the body meets stops it. */
    Sweeper PLAIN = (geometry, bodyId, distance, rotation) -> geometry.sweep(bodyId, distance, rotation);

    /**
     * @param geometry the world
     * @param bodyId   the robot's body
     * @param distance arc length, mm, negative backwards
     * @param rotation heading change, radians
     * @return the free part of the motion and the pose reached, as {@link GeometryClient#sweep} answers
     */
    SweepResult sweep(GeometryClient geometry, int bodyId, double distance, double rotation);
}
