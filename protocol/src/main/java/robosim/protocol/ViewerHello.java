package robosim.protocol;

import com.fasterxml.jackson.annotation.JsonInclude;

/**
 * The first message of a viewer's connection.
 *
 * @param name  a name for the viewer, for the Environment's log
 * @param token the run secret (see {@link RunSecret}), or null; needed unless the Environment lets
 *              anyone watch ({@code env --public-view})
 */
public record ViewerHello(String name, @JsonInclude(JsonInclude.Include.NON_NULL) String token) implements Message {
    /** @param name a name for the viewer; no secret is presented */
    public ViewerHello(String name) {
        this(name, null);
    }

    /** @return the hello with the secret masked */
    @Override
    public String toString() {
        return "ViewerHello[name=" + name + ", token=" + RunSecret.masked(token) + "]";
    }
}
