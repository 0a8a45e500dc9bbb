package org.jecosys.sim;

import org.jecosys.math.Camera;

/**
 * The registered views of a {@link Simulation} or an {@link OpenWorld}: a small array replaced whole
 * on each change (copy on write), so a step reads one array without a lock. Static helpers.
 */
final class ViewLists {
    private ViewLists() {
    }

    /** {@return whether {@code list} holds this very camera} No allocation. */
    static boolean contains(Camera[] list, Camera c) {
        for (Camera v : list) {
            if (v == c) {
                return true;
            }
        }
        return false;
    }

    /**
     * {@return a new array: {@code list} and {@code view} after it} Allocates.
     *
     * @param most    the most views {@code list} may hold before this one, for the message
     * @param holder  what follows the views, for the messages ("a simulation", "an open world")
     * @throws IllegalArgumentException when {@code view} is there already
     * @throws IllegalStateException    when {@code list} holds {@code most} views already
     */
    static Camera[] with(Camera[] list, Camera view, int most, String holder) {
        if (contains(list, view)) {
            throw new IllegalArgumentException("this view is already registered");
        }
        if (list.length >= most) {
            throw new IllegalStateException(holder + " follows at most " + Simulation.MAX_VIEWS
                    + " views (Simulation.MAX_VIEWS): the step's camera and " + most + " registered ones");
        }
        Camera[] n = java.util.Arrays.copyOf(list, list.length + 1);
        n[list.length] = view;
        return n;
    }

    /** {@return a new array without {@code view}, or {@code list} itself when it does not hold it} */
    static Camera[] without(Camera[] list, Camera view) {
        for (int i = 0; i < list.length; i++) {
            if (list[i] == view) {
                Camera[] n = new Camera[list.length - 1];
                System.arraycopy(list, 0, n, 0, i);
                System.arraycopy(list, i + 1, n, i, list.length - i - 1);
                return n;
            }
        }
        return list;
    }
}
