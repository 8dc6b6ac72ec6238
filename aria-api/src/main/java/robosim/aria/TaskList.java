package robosim.aria;

import java.util.ArrayList;
import java.util.List;
import java.util.logging.Level;
import java.util.logging.Logger;

/**
 * Named tasks run once per robot cycle, as ARIA's sync tasks: higher positions run first, equal
 * positions in the order they were added. A task that throws is logged and removed, so one broken
 * task cannot stop the robot's cycle.
 */
final class TaskList {
    private static final Logger LOG = Logger.getLogger(TaskList.class.getName());

    private record Task(String name, int position, Runnable body) { }

    private final String kind;
    private final List<Task> tasks = new ArrayList<>();

    TaskList(String kind) {
        this.kind = kind;
    }

    synchronized void add(String name, int position, Runnable body) {
        if (name == null || body == null) {
            throw new IllegalArgumentException("a " + kind + " task needs a name and a body");
        }
        remove(name);
        int at = 0;
        while (at < tasks.size() && tasks.get(at).position() >= position) {
            at++;
        }
        tasks.add(at, new Task(name, position, body));
    }

    synchronized boolean remove(String name) {
        return tasks.removeIf(t -> t.name().equals(name));
    }


    /** @return the task of that name, or null */
    synchronized ArSyncTask find(String name) {
        return tasks.stream().filter(t -> t.name().equals(name)).findFirst().map(this::view).orElse(null);
    }

    /** @return the first task with that body, or null */
    synchronized ArSyncTask find(Runnable body) {
        return tasks.stream().filter(t -> t.body() == body).findFirst().map(this::view).orElse(null);
    }

    /** @return whether a task with that body was there; the first is removed */
    synchronized boolean remove(Runnable body) {
        for (int i = 0; i < tasks.size(); i++) {
            if (tasks.get(i).body() == body) {
                tasks.remove(i);
                return true;
            }
        }
        return false;
    }

    /** @return the tasks in running order */
    synchronized java.util.List<ArSyncTask> list() {
        return tasks.stream().map(this::view).toList();
    }

    /** Logs the list's tasks in running order, one a line, as ARIA's {@code ArSyncTask::log} does. */
    void log(String robot) {
        List<ArSyncTask> all = list();
        LOG.info(() -> "robot " + robot + ": " + kind + " tasks (" + all.size() + "):"
                + all.stream().map(t -> "\n  " + t).reduce("", String::concat));
    }

    private ArSyncTask view(Task t) {
        return new ArSyncTask(t.name(), t.position(), t.body(), kind);
    }

    void runAll(String robot) {
        List<Task> snapshot;
        synchronized (this) {
            snapshot = List.copyOf(tasks);
        }
        for (Task t : snapshot) {
            try {
                t.body().run();
            } catch (RuntimeException e) {
                LOG.log(Level.WARNING, "robot " + robot + ": " + kind + " task '" + t.name()
                        + "' threw and was removed", e);
                remove(t.name());
            }
        }
    }
}
