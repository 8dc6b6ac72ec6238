package robosim.params;

import robosim.protocol.RobotParameters;
import robosim.protocol.SonarUnit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.params.provider.ValueSource;

/** Every shipped robot reads the same in both forms, and both match docs/ARIA-SEMANTICS.md. */
class ShippedRobotFormsTest {
    /** The p3dx of docs/ARIA-SEMANTICS.md: body, speeds, sonar table, laser at x 18. */
    private static final RobotParameters P3DX = new RobotParameters("Pioneer", "p3dx",
            250, 425, 210, 301, 2200, 500, 300, 300, 100, 100, 0.0056, 5000, List.of(
            new SonarUnit(0, 69, 136, 90), new SonarUnit(1, 114, 119, 50),
            new SonarUnit(2, 148, 78, 30), new SonarUnit(3, 166, 27, 10),
            new SonarUnit(4, 166, -27, -10), new SonarUnit(5, 148, -78, -30),
            new SonarUnit(6, 114, -119, -50), new SonarUnit(7, 69, -136, -90),
            new SonarUnit(8, -157, -136, -90), new SonarUnit(9, -203, -119, -130),
            new SonarUnit(10, -237, -78, -150), new SonarUnit(11, -255, -27, -170),
            new SonarUnit(12, -255, 27, 170), new SonarUnit(13, -237, 78, 150),
            new SonarUnit(14, -203, 119, 130), new SonarUnit(15, -157, 136, 90)),
            18, 0, 0, 8000);

    /** The p3at of docs/ARIA-SEMANTICS.md: body, speeds, sonar table, laser at x 160. */
    private static final RobotParameters P3AT = new RobotParameters("Pioneer", "p3at",
            500, 505, 313, 313, 1200, 300, 300, 300, 100, 100, 0.0034, 5000, List.of(
            new SonarUnit(0, 147, 136, 90), new SonarUnit(1, 193, 119, 50),
            new SonarUnit(2, 227, 79, 30), new SonarUnit(3, 245, 27, 10),
            new SonarUnit(4, 245, -27, -10), new SonarUnit(5, 227, -79, -30),
            new SonarUnit(6, 193, -119, -50), new SonarUnit(7, 147, -136, -90),
            new SonarUnit(8, -144, -136, -90), new SonarUnit(9, -189, -119, -130),
            new SonarUnit(10, -223, -79, -150), new SonarUnit(11, -241, -27, -170),
            new SonarUnit(12, -241, 27, 170), new SonarUnit(13, -223, 79, 150),
            new SonarUnit(14, -189, 119, 130), new SonarUnit(15, -144, 136, 90)),
            160, 0, 0, 8000);

    static Stream<Arguments> robots() {
        return Stream.of(Arguments.of("p3dx", P3DX), Arguments.of("p3at", P3AT));
    }

    private static Path shipped(String name) {
        return ShippedRobots.dir().resolve(name);
    }

    @ParameterizedTest(name = "{0}.p and {0}.xml give equal records")
    @ValueSource(strings = {"p3dx", "p3at"})
    void bothFormsGiveEqualRecords(String robot) {
        assertEquals(RobotParametersReader.read(shipped(robot + ".p")),
                RobotParametersReader.read(shipped(robot + ".xml")));
    }

    @ParameterizedTest(name = "{0} is within the Environment's physical bounds")
    @ValueSource(strings = {"p3dx.p", "p3dx.xml", "p3at.p", "p3at.xml", "scout.p", "scout.xml"})
    void everyShippedRobotIsWithinTheEnvironmentsBounds(String file) {
        assertNull(RobotParametersReader.read(shipped(file)).violation());
    }

    @ParameterizedTest(name = "{0}.p matches docs/ARIA-SEMANTICS.md")
    @MethodSource("robots")
    void pFormMatchesAria(String robot, RobotParameters aria) {
        assertEquals(aria, ParameterFileReader.read(shipped(robot + ".p")));
    }

    @ParameterizedTest(name = "{0}.xml matches docs/ARIA-SEMANTICS.md")
    @MethodSource("robots")
    void xmlFormMatchesAria(String robot, RobotParameters aria) {
        assertEquals(aria, XmlParameterFileReader.read(shipped(robot + ".xml")));
    }

    @ParameterizedTest(name = "{0}.xml keeps all 16 repeated sonarUnit elements")
    @ValueSource(strings = {"p3dx", "p3at"})
    void xmlFormKeepsEveryRepeatedSonarUnit(String robot) {
        RobotParameters read = XmlParameterFileReader.read(shipped(robot + ".xml"));

        assertEquals(16, read.sonarUnits().size());
        assertEquals(15, read.sonarUnits().get(15).index());
    }

    @ParameterizedTest(name = "{0}: laser pose from both forms")
    @MethodSource("robots")
    void laserPoseMatchesAriaInBothForms(String robot, RobotParameters aria) {
        for (String form : List.of(".p", ".xml")) {
            RobotParameters read = RobotParametersReader.read(shipped(robot + form));
            assertEquals(List.of(aria.laserX(), 0.0, 0.0, 8000.0),
                    List.of(read.laserX(), read.laserY(), read.laserTh(), read.laserMaxRange()), robot + form);
        }
    }
}
