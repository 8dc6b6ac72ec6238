package robosim.comms;

/** Where robots are and what lies between them, as the simulation knows it. */
public interface Positions {
    /**
     * @param robot a robot's name
     * @return its true position as {x, y} in mm
     */
    double[] of(String robot);

    /**
     * @param from a robot
     * @param to   another robot
     * @return whether no wall or obstacle lies on the straight line between them
     */
    boolean clear(String from, String to);
}
