package robosim.panel.model;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class EnvironmentLineTest {
    @Test
    void theLineEnvPrintsOnceBoundGivesBothPorts() {
        assertEquals(new EnvironmentLine("empty-room", "127.0.0.1", 45723, "127.0.0.1", 43143),
                EnvironmentLine.parse("Environment: world empty-room, robots on 127.0.0.1:45723, viewers on"
                        + " 127.0.0.1:43143").orElseThrow());
    }

    @Test
    void otherLinesAreNotIt() {
        assertTrue(EnvironmentLine.parse("Waiting for robots: r1, r2").isEmpty());
    }

    @Test
    void anEnvironmentOnEveryAddressIsReachedOnLoopback() {
        assertEquals("127.0.0.1", new EnvironmentLine("w", "0.0.0.0", 1, "0.0.0.0", 2).clientHost());
    }
}
