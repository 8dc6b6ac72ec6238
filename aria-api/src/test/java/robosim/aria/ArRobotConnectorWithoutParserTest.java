package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.Test;

/** A connector made with no parser, as ARIA's singleThreadLoopExample.cpp makes one (NULL). */
class ArRobotConnectorWithoutParserTest {
    @Test
    void withoutAParserNoArgumentsAreParsedAndTheDefaultsStand() {
        Aria.init();
        ByteArrayOutputStream log = new ByteArrayOutputStream();
        ArLog.setStream(new PrintStream(log, true, StandardCharsets.UTF_8));
        try {
            ArRobotConnector connector = new ArRobotConnector(null, new ArRobot());
            assertFalse(connector.parseArgs(), "ARIA's parseArgs() without a parser");
            assertFalse(Aria.parseArgs(), "the connector's callback answers the same");
            assertNull(connector.getRemoteHost());
            assertEquals(8101, connector.getRemoteRobotTcpPort());
            assertEquals("Aria::parseArgs: Failed, parse arg functor 'ArRobotConnector' (75) returned false\n",
                    log.toString(StandardCharsets.UTF_8), "ARIA's line, and nothing of a parser");
        } finally {
            ArLog.setStream(null);
            Aria.uninit();
        }
    }
}
