package robosim.env.world.xml;

import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.core.JsonStreamContext;
import com.fasterxml.jackson.core.JsonToken;
import com.fasterxml.jackson.dataformat.xml.deser.FromXmlParser;
import java.io.IOException;
import javax.xml.stream.XMLStreamConstants;
import javax.xml.stream.XMLStreamReader;

/**
 * What Jackson's token stream hides about the XML. Jackson reports attributes and child elements
 * alike as fields; the StAX reader underneath tells them apart: while an attribute's value is the
 * current token, the reader still stands on the start tag that carries it.
 */
final class XmlNodes {
    private XmlNodes() {
    }

    /** @return whether the current value is an attribute (rather than a child element) */
    static boolean isAttribute(JsonParser p) throws IOException {
        if (!p.hasToken(JsonToken.VALUE_STRING) || !(p instanceof FromXmlParser xml)) {
            return false;
        }
        String name = p.currentName();
        XMLStreamReader reader = xml.getStaxReader();
        return name != null && reader.getEventType() == XMLStreamConstants.START_ELEMENT
                && reader.getAttributeValue(null, name) != null;
    }

    /** @return the element whose attribute or child the current token is */
    static String enclosingTag(JsonParser p) {
        JsonStreamContext context = p.getParsingContext();
        if (p.hasToken(JsonToken.START_OBJECT) || p.hasToken(JsonToken.START_ARRAY)) {
            context = context.getParent();
        }
        JsonStreamContext parent = context == null ? null : context.getParent();
        return parent == null || parent.getCurrentName() == null ? "world" : parent.getCurrentName();
    }

    /** @return the 1-based line the current token starts on */
    static int line(JsonParser p) {
        return p.currentTokenLocation().getLineNr();
    }
}
