package robosim.aria;

import java.util.ArrayList;
import java.util.List;
import robosim.protocol.Command;

/** A p3dx that keeps what it would send instead of sending it, for tests of what calls request. */
class RecordingRobot extends ArRobot {
    final List<Command> sent = new ArrayList<>();

    RecordingRobot() {
        super("r", "127.0.0.1", 5000, Cycles.p3dx());
    }

    @Override
    protected void request(Command command) {
        sent.add(command);
    }

    /** @return what was sent since the last call, and forgets it */
    List<Command> take() {
        List<Command> c = List.copyOf(sent);
        sent.clear();
        return c;
    }
}
