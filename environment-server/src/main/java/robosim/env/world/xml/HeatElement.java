package robosim.env.world.xml;

import com.fasterxml.jackson.dataformat.xml.annotation.JacksonXmlProperty;

/** A {@code <heat>} element: a heat source's position and intensity. */
class HeatElement extends Element {
    @JacksonXmlProperty(isAttribute = true)
    String x;
    @JacksonXmlProperty(isAttribute = true)
    String y;
    @JacksonXmlProperty(isAttribute = true)
    String intensity;

    @Override
    String tag() {
        return "heat";
    }
}
