package robosim.env.world.xml;

import com.fasterxml.jackson.dataformat.xml.annotation.JacksonXmlProperty;

/** A {@code <comms>} element: how messages travel between robots, every attribute optional. */
final class CommsElement extends Element {
    @JacksonXmlProperty(isAttribute = true)
    String range;
    @JacksonXmlProperty(isAttribute = true)
    String wallsBlock;
    @JacksonXmlProperty(isAttribute = true)
    String latency;
    @JacksonXmlProperty(isAttribute = true)
    String loss;
    @JacksonXmlProperty(isAttribute = true)
    String maxBytes;

    @Override
    String tag() {
        return "comms";
    }
}
