package com.example.jmemeadow;

import com.jme3.system.Timer;

/** A timer whose every frame lasts the same time: the test mode's pictures do not depend on the machine's speed. */
final class FixedTimer extends Timer {
    private final float frameSeconds;
    private long frames;

    FixedTimer(float frameSeconds) {
        this.frameSeconds = frameSeconds;
    }

    @Override
    public long getTime() {
        return Math.round(frames * (double) frameSeconds * 1e9);
    }

    @Override
    public long getResolution() {
        return 1_000_000_000L;
    }

    @Override
    public float getFrameRate() {
        return 1 / frameSeconds;
    }

    @Override
    public float getTimePerFrame() {
        return frameSeconds;
    }

    @Override
    public void update() {
        frames++;
    }

    @Override
    public void reset() {
        frames = 0;
    }
}
