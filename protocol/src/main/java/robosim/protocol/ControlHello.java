package robosim.protocol;

import com.fasterxml.jackson.annotation.JsonInclude;

/**
 * The first message of a control client on the viewer port: a client that changes the run (the
 * {@link CommsUpdate comms settings}, and {@link ControlRequest run control}) rather than watching
 * it. It receives no snapshots; a comms change is answered with the settings now in force, or with a
 * {@link Bye} saying why it was refused; a control request with a {@link ControlReply}.
 *
 * @param name  a name for the client, for the Environment's log
 * @param token the run secret (see {@link RunSecret}); a control client must present it when the run has one
 */
public record ControlHello(String name, @JsonInclude(JsonInclude.Include.NON_NULL) String token) implements Message {
    /** @return the hello with the secret masked */
    @Override
    public String toString() {
        return "ControlHello[name=" + name + ", token=" + RunSecret.masked(token) + "]";
    }
}
