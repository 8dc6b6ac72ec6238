package robosim.params;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robosim.protocol.RobotParameters;
import robosim.protocol.SonarUnit;

/** The original RoboSim's own parameter XML, {@code <robot><params>...}, as its user manual prints it. */
class OriginalXmlLayoutTest {
    /** The manual's example as printed: the whole sonar section sits in a comment. */
    private static final String MANUAL_EXAMPLE = """
            <?xml version="1.0"?>
            <robot>
              <params>
                <class>Pioneer</class>
                <subclass>p3dx</subclass>
                <robotRadius>250</robotRadius>
                <robotDiagonal>120</robotDiagonal>
                <robotWidth>425</robotWidth>
                <robotLength>511</robotLength>
                <maxRVelocity>500</maxRVelocity>
                <maxVelocity>2200</maxVelocity>
                <sonarNum>16</sonarNum>
                <!--
                <sonar>
                  <sonarUnit>
                    <sonarNumber>0</sonarNumber>
                    <sonarX>69</sonarX>
                    <sonarY>136</sonarY>
                    <sonarTh>90</sonarTh>
                  </sonarUnit>
                  ...
                </sonar>
                -->
              </params>
            </robot>
            """;

    @TempDir
    Path dir;

    private Path write(String name, String text) throws IOException {
        return Files.writeString(dir.resolve(name), text, StandardCharsets.UTF_8);
    }

    private static RobotParameters shippedP3dx() {
        return ParameterFileReader.read(ShippedRobots.dir().resolve("p3dx.p"));
    }

    @Test
    void theManualsExampleTakesItsSonarsFromTheP3dxModel() throws IOException {
        Files.copy(ShippedRobots.dir().resolve("p3dx.p"), dir.resolve("p3dx.p"));
        RobotParameters p = XmlParameterFileReader.read(write("manual.xml", MANUAL_EXAMPLE));
        assertEquals(shippedP3dx().sonarUnits(), p.sonarUnits());
        assertEquals(List.of("Pioneer", "p3dx"), List.of(p.robotClass(), p.subclass()));
        assertEquals(List.of(250.0, 425.0, 255.5, 255.5, 2200.0, 500.0), List.of(p.robotRadius(), p.robotWidth(),
                p.robotLengthFront(), p.robotLengthRear(), p.maxVelocity(), p.maxRVelocity()));
    }

    @Test
    void theShippedOriginalFileLoadsWithTheShippedSonars() {
        RobotParameters p = RobotParametersReader.read(ShippedRobots.dir().resolve("p3dx-original.xml"));
        assertEquals(shippedP3dx().sonarUnits(), p.sonarUnits());
    }

    @Test
    void sonarUnitsGivenAsChildElementsAreRead() throws IOException {
        Path file = write("two.xml", """
                <robot><params>
                  <subclass>tiny</subclass>
                  <sonarNum>2</sonarNum>
                  <sonar>
                    <sonarUnit><sonarNumber>1</sonarNumber><sonarX>-5</sonarX><sonarY>6</sonarY><sonarTh>180</sonarTh></sonarUnit>
                    <sonarUnit><sonarNumber>0</sonarNumber><sonarX>5</sonarX><sonarY>6</sonarY><sonarTh>0</sonarTh></sonarUnit>
                  </sonar>
                </params></robot>
                """);
        assertEquals(List.of(new SonarUnit(0, 5, 6, 0), new SonarUnit(1, -5, 6, 180)),
                XmlParameterFileReader.read(file).sonarUnits());
    }

    @Test
    void noSonarsAndNoModelIsAClearError() throws IOException {
        Path file = write("lost.xml", """
                <robot>
                  <params>
                    <class>Pioneer</class>
                    <subclass>p9zz</subclass>
                  </params>
                </robot>
                """);
        ParameterFileException e = assertThrows(ParameterFileException.class, () -> XmlParameterFileReader.read(file));
        assertEquals(file + ":4: the file gives no sonar units and there is no model of subclass 'p9zz' to take them "
                + "from (looked for p9zz.p beside the file and in testLoadFiles/robots)", e.getMessage());
    }

    @Test
    void aSonarUnitMissingAValueNamesTheLine() throws IOException {
        Path file = write("half.xml", """
                <robot><params>
                  <sonar>
                    <sonarUnit>
                      <sonarNumber>0</sonarNumber><sonarX>5</sonarX><sonarY>6</sonarY>
                    </sonarUnit>
                  </sonar>
                </params></robot>
                """);
        ParameterFileException e = assertThrows(ParameterFileException.class, () -> XmlParameterFileReader.read(file));
        assertEquals(file + ":3: sonarUnit has no <sonarTh> (it needs sonarNumber, sonarX, sonarY, sonarTh)",
                e.getMessage());
    }

    @Test
    void anUnknownElementInParamsIsNamed() throws IOException {
        Path file = write("odd.xml", "<robot>\n<params>\n<wheelCount>4</wheelCount>\n</params>\n</robot>\n");
        ParameterFileException e = assertThrows(ParameterFileException.class, () -> XmlParameterFileReader.read(file));
        assertEquals(file + ":3: unknown element <wheelCount> in <params>", e.getMessage());
    }

    @Test
    void aRobotWithoutParamsIsAnError() throws IOException {
        Path file = write("empty.xml", "<robot>\n</robot>\n");
        ParameterFileException e = assertThrows(ParameterFileException.class, () -> XmlParameterFileReader.read(file));
        assertEquals(file + ":1: <robot> has no <params>", e.getMessage());
    }
}
