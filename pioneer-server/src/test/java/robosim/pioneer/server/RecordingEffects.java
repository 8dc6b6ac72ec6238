package robosim.pioneer.server;

import java.util.List;
import java.util.function.Supplier;
import robosim.pioneer.PioneerPacket;
import robosim.protocol.Command;

/**
 * A command handler's effects for tests: keeps the robot's requests and the log lines in the lists
 * given, and ignores the rest.
 *
 * @param requests where the requests go
 * @param log      where the log lines go
 */
record RecordingEffects(List<Command> requests, List<String> log) implements CommandHandler.Effects {
    @Override
    public void request(Command c) {
        requests.add(c);
    }

    @Override
    public void reply(PioneerPacket p) {
    }

    @Override
    public void resetOdometry() {
    }

    @Override
    public void resetToStart() {
    }

    @Override
    public void simStat(int mode) {
    }

    @Override
    public void close(String reason) {
    }

    @Override
    public void simExit(int code) {
    }

    @Override
    public void log(String kind, Supplier<String> line) {
        log.add(line.get());
    }
}
