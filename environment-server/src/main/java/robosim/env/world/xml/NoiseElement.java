package robosim.env.world.xml;

import com.fasterxml.jackson.dataformat.xml.annotation.JacksonXmlProperty;

/** A {@code <noise>} element: the sonar, laser and odometry noise of the world, each optional. */
final class NoiseElement extends Element {
    @JacksonXmlProperty(isAttribute = true)
    String sonar;
    @JacksonXmlProperty(isAttribute = true)
    String laser;
    @JacksonXmlProperty(isAttribute = true)
    String odometry;

    @Override
    String tag() {
        return "noise";
    }
}
