package robosim.env.core;

import java.util.function.Supplier;

/**
 * A value made when first asked for and then kept, whichever of the threads reading the robots'
 * sensors asks first.
 *
 * @param <T> the value's type
 */
final class Once<T> implements Supplier<T> {
    private Supplier<T> make;
    private T value;

    /** @param make makes the value, once */
    Once(Supplier<T> make) {
        this.make = make;
    }

    @Override
    public synchronized T get() {
        if (make != null) {
            value = make.get();
            make = null;
        }
        return value;
    }
}
