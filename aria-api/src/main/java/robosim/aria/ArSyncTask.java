package robosim.aria;

/**
 * One task of a robot's cycle, as ARIA's {@code ArSyncTask} names it ({@link ArRobot#findTask},
 * {@link ArRobot#findUserTask}): a user task or a sensor-interpretation task, with its name,
 * position and body. Running it runs the body once, outside the cycle.
 */
public final class ArSyncTask {
    private final String name;
    private final int position;
    private final Runnable functor;
    private final String list;

    ArSyncTask(String name, int position, Runnable functor, String list) {
        this.name = name;
        this.position = position;
        this.functor = functor;
        this.list = list;
    }

    /** @return the task's name */
    public String getName() {
        return name;
    }

    /** @return its position: higher positions run first in the cycle */
    public int getPosition() {
        return position;
    }

    /** @return the task's body (ARIA's functor) */
    public Runnable getFunctor() {
        return functor;
    }

    /** Runs the task's body once. */
    public void run() {
        functor.run();
    }

    /** @return the task as ARIA's {@code ArSyncTask::log} lists it: its name, position and list */
    @Override
    public String toString() {
        return name + " (position " + position + ", " + list + " tasks)";
    }
}
