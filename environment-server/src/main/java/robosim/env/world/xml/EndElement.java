package robosim.env.world.xml;

import com.fasterxml.jackson.dataformat.xml.annotation.JacksonXmlProperty;

/** An {@code <end>} element: when the run ends of itself. */
final class EndElement extends Element {
    @JacksonXmlProperty(isAttribute = true)
    String when;
    @JacksonXmlProperty(isAttribute = true)
    String steps;

    @Override
    String tag() {
        return "end";
    }
}
