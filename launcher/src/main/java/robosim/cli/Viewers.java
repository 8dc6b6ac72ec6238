package robosim.cli;

import java.time.Duration;
import java.util.List;
import robosim.protocol.recording.SnapshotListener;
import robosim.viewer.net.ViewerClient;
import robosim.viewer.net.ViewerOptions;

/** Makes the viewer of the commands that run an Environment and watch it themselves. */
final class Viewers {
    private Viewers() {
    }

    static ViewerClient client(String host, int port, String name, List<SnapshotListener> listeners,
                               Duration readTimeout) {
        return new ViewerClient(ViewerOptions.of(host, port).withName(name).withReadTimeout(readTimeout), listeners);
    }
}
