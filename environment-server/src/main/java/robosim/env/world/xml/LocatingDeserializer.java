package robosim.env.world.xml;

import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.databind.BeanDescription;
import com.fasterxml.jackson.databind.DeserializationConfig;
import com.fasterxml.jackson.databind.DeserializationContext;
import com.fasterxml.jackson.databind.JsonDeserializer;
import com.fasterxml.jackson.databind.deser.BeanDeserializerModifier;
import com.fasterxml.jackson.databind.deser.std.DelegatingDeserializer;
import java.io.IOException;

/**
 * Wraps the bean deserializer of each {@link Element} class to record the line the element
 * starts on: when the bean deserializer is entered the current token is the element's start
 * (its {@code START_OBJECT}, or the empty text of {@code <wall/>}), located at its start tag.
 */
final class LocatingDeserializer extends DelegatingDeserializer {
    private static final long serialVersionUID = 1L;

    /** Installs the wrapper on element classes. */
    static final class Modifier extends BeanDeserializerModifier {
        private static final long serialVersionUID = 1L;

        @Override
        public JsonDeserializer<?> modifyDeserializer(DeserializationConfig config, BeanDescription bean,
                                                      JsonDeserializer<?> deserializer) {
            return Element.class.isAssignableFrom(bean.getBeanClass())
                    ? new LocatingDeserializer(deserializer) : deserializer;
        }
    }

    LocatingDeserializer(JsonDeserializer<?> delegate) {
        super(delegate);
    }

    @Override
    protected JsonDeserializer<?> newDelegatingInstance(JsonDeserializer<?> delegate) {
        return new LocatingDeserializer(delegate);
    }

    @Override
    public Object deserialize(JsonParser p, DeserializationContext context) throws IOException {
        int line = XmlNodes.line(p);
        if (XmlNodes.isAttribute(p)) {
            throw new XmlProblem(line, "unknown attribute " + p.currentName() + " on <"
                    + XmlNodes.enclosingTag(p) + ">: <" + p.currentName() + "> is an element");
        }
        Element element = (Element) super.deserialize(p, context);
        element.locate(line);
        return element;
    }
}
