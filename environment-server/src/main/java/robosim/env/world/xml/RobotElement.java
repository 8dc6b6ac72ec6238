package robosim.env.world.xml;

import com.fasterxml.jackson.dataformat.xml.annotation.JacksonXmlProperty;

/** A {@code <robot>} element: a robot that must connect, its start pose and parameter file. */
final class RobotElement extends Element {
    @JacksonXmlProperty(isAttribute = true)
    String name;
    @JacksonXmlProperty(isAttribute = true)
    String type;
    @JacksonXmlProperty(isAttribute = true)
    String x;
    @JacksonXmlProperty(isAttribute = true)
    String y;
    @JacksonXmlProperty(isAttribute = true)
    String th;
    @JacksonXmlProperty(isAttribute = true)
    String params;

    @Override
    String tag() {
        return "robot";
    }
}
