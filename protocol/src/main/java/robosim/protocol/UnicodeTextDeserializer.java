package robosim.protocol;

import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.databind.DeserializationContext;
import com.fasterxml.jackson.databind.JsonMappingException;
import com.fasterxml.jackson.databind.deser.std.StringDeserializer;
import java.io.IOException;

/**
 * Reads text and refuses any that is not valid Unicode. Jackson's Smile parser reads the 3-byte
 * form of a lone surrogate (which is not UTF-8) into a string, and JSON may escape one; either
 * string can be decoded but never encoded again, so a peer's text that the Environment passes on
 * (a robot's words to the viewers, a message to another robot) would fail when it is sent.
 */
final class UnicodeTextDeserializer extends StringDeserializer {
    private static final long serialVersionUID = 1L;

    @Override
    public String deserialize(JsonParser p, DeserializationContext context) throws IOException {
        String text = super.deserialize(p, context);
        int bad = loneSurrogate(text);
        if (bad >= 0) {
            throw new JsonMappingException(p, "text with a lone surrogate at character " + bad
                    + ": text must be valid UTF-8");
        }
        return text;
    }

    /** @return the index of the first surrogate not in a pair, or -1 if there is none (or no text) */
    static int loneSurrogate(String text) {
        if (text == null) {
            return -1;
        }
        for (int i = 0; i < text.length(); i++) {
            char c = text.charAt(i);
            if (Character.isHighSurrogate(c) && i + 1 < text.length() && Character.isLowSurrogate(text.charAt(i + 1))) {
                i++;
            } else if (Character.isSurrogate(c)) {
                return i;
            }
        }
        return -1;
    }
}
