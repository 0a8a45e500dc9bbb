package org.jecosys.app;

/**
 * The viewer's keyboard and mouse input as events, so that no key tap is lost at any frame rate
 * (issue: a 12 ms tap of P was missed at 10 fps when keys were polled once per frame). GLFW's
 * callbacks, which run inside {@code glfwPollEvents} on the render thread, call {@link #key},
 * {@link #mouseButton} and {@link #scroll}; the frame then calls {@link #beginFrame()} and reads
 * what happened since the last frame: every press in order ({@link #presses()}), whether a key is
 * held ({@link #held}: down now, or pressed since the last frame even if already released, so a
 * tap shorter than a frame still moves the camera for one frame), and the mouse buttons' presses
 * and releases. No GLFW here, so tests drive it headless.
 *
 * <p>Render thread only (GLFW calls callbacks on the thread that polls). No allocation: events go to
 * a fixed ring of {@link #CAPACITY}; if more arrive between two frames the oldest are dropped.
 */
final class ViewerInput {
    /** GLFW's action codes. */
    static final int RELEASE = 0;
    static final int PRESS = 1;
    static final int REPEAT = 2;
    /** GLFW's modifier bits. */
    static final int MOD_SHIFT = 1;
    static final int MOD_CONTROL = 2;
    /** Events kept between two frames. */
    static final int CAPACITY = 256;
    /** Highest key code tracked (GLFW_KEY_LAST is 348). */
    static final int KEYS = 349;
    static final int BUTTONS = 8;

    // queued by callbacks: key (or -1 - button for mouse buttons), action, mods
    private final int[] queue = new int[CAPACITY * 3];
    private int head;
    private int count;
    // this frame's presses, in order
    private final int[] pressKeys = new int[CAPACITY];
    private final int[] pressMods = new int[CAPACITY];
    private int presses;
    private final boolean[] down = new boolean[KEYS];
    private final boolean[] tapped = new boolean[KEYS];
    private final boolean[] consumed = new boolean[KEYS];
    private final boolean[] buttonDown = new boolean[BUTTONS];
    private final boolean[] buttonPressed = new boolean[BUTTONS];
    private final boolean[] buttonReleased = new boolean[BUTTONS];
    private double scrollPending;
    private double scroll;

    /** GLFW key callback. Render thread; no allocation. */
    void key(int key, int action, int mods) {
        if (key < 0 || key >= KEYS || action == REPEAT) {
            return;
        }
        push(key, action, mods);
    }

    /** GLFW mouse button callback. Render thread; no allocation. */
    void mouseButton(int button, int action, int mods) {
        if (button < 0 || button >= BUTTONS || action == REPEAT) {
            return;
        }
        push(-1 - button, action, mods);
    }

    /** GLFW scroll callback: vertical wheel steps. Render thread; no allocation. */
    void scroll(double dy) {
        scrollPending += dy;
    }

    private void push(int code, int action, int mods) {
        if (count == CAPACITY) { // drop the oldest
            head = (head + 1) % CAPACITY;
            count--;
        }
        int at = 3 * ((head + count) % CAPACITY);
        queue[at] = code;
        queue[at + 1] = action;
        queue[at + 2] = mods;
        count++;
    }

    /** Takes the events queued since the last frame. Call once per frame, after polling events. */
    void beginFrame() {
        presses = 0;
        java.util.Arrays.fill(tapped, false);
        java.util.Arrays.fill(buttonPressed, false);
        java.util.Arrays.fill(buttonReleased, false);
        for (; count > 0; count--) {
            int at = 3 * head;
            head = (head + 1) % CAPACITY;
            int code = queue[at];
            int action = queue[at + 1];
            if (code >= 0) {
                if (action == PRESS) {
                    down[code] = true;
                    tapped[code] = true;
                    consumed[code] = false;
                    pressKeys[presses] = code;
                    pressMods[presses] = queue[at + 2];
                    presses++;
                } else {
                    down[code] = false;
                }
            } else {
                int b = -1 - code;
                if (action == PRESS) {
                    buttonDown[b] = true;
                    buttonPressed[b] = true;
                } else {
                    buttonDown[b] = false;
                    buttonReleased[b] = true;
                }
            }
        }
        scroll = scrollPending;
        scrollPending = 0;
    }

    /** {@return the number of key presses since the last frame} */
    int presses() {
        return presses;
    }

    /** {@return the key of press i of this frame, i in [0, presses())} */
    int pressKey(int i) {
        return pressKeys[i];
    }

    /** {@return the modifier bits held at press i of this frame} */
    int pressMods(int i) {
        return pressMods[i];
    }

    /** Whether the key is down now or was pressed since the last frame, and not {@link #consume consumed}. */
    boolean held(int key) {
        return key >= 0 && key < KEYS && (down[key] || tapped[key]) && !consumed[key];
    }

    /** Whether the key is down now (the last event said so). */
    boolean down(int key) {
        return key >= 0 && key < KEYS && down[key];
    }

    /** Treats the key as up until it is pressed again: S of Ctrl+S saves and does not walk back. */
    void consume(int key) {
        if (key >= 0 && key < KEYS) {
            consumed[key] = true;
        }
    }

    /** {@return +1, -1 or 0 from two held keys} */
    double axis(int plus, int minus) {
        return (held(plus) ? 1 : 0) - (held(minus) ? 1 : 0);
    }

    /** {@return whether the mouse button is down now} */
    boolean buttonDown(int button) {
        return buttonDown[button];
    }

    /** {@return whether the mouse button was pressed since the last frame (even if already released)} */
    boolean buttonPressed(int button) {
        return buttonPressed[button];
    }

    /** {@return whether the mouse button was released since the last frame} */
    boolean buttonReleased(int button) {
        return buttonReleased[button];
    }

    /** {@return the wheel steps since the last frame (positive: away from the user)} */
    double scrolled() {
        return scroll;
    }
}
