package robosim.env.net;

import robosim.protocol.ControlReply;
import robosim.protocol.ControlRequest;

/** Where the viewer port hands a control client's requests ({@link RunControl}). */
@FunctionalInterface
interface ControlRequests {
    /** Until run control is there: every request is refused, naming why. */
    ControlRequests NONE = (c, r) -> c.send(new ControlReply(r.id(), false,
            "this Environment takes no run control"));

    /**
     * A control client sent a request.
     *
     * @param c the client
     * @param r the request
     */
    void received(Connection c, ControlRequest r);
}
