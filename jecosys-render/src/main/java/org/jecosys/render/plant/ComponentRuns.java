package org.jecosys.render.plant;

/**
 * The component ranges that hold the plants a {@link PlantBatches} listed: what the frame uploads of the
 * components' render states. Plants are added in ascending component order; a gap of at most
 * {@link PlantBatches#GAP} components between two listed plants joins their ranges (one upload rather
 * than two), so the ranges are ascending and disjoint. Render thread; sized for every plant at
 * construction, no allocation after.
 */
public final class ComponentRuns {
    private final int[] start;
    private final int[] end;
    private int count;

    ComponentRuns(int plants) {
        start = new int[Math.max(1, plants)];
        end = new int[Math.max(1, plants)];
    }

    void clear() {
        count = 0;
    }

    /** Adds the components [c0, c1) of the next listed plant, whose first component is above the last one's. */
    void add(int c0, int c1) {
        if (count > 0 && c0 - end[count - 1] <= PlantBatches.GAP) {
            end[count - 1] = c1;
        } else {
            start[count] = c0;
            end[count++] = c1;
        }
    }

    /** {@return the number of ranges} */
    public int count() {
        return count;
    }

    /**
     * {@return the first component of range {@code i}}
     *
     * @param i range index, in [0, count())
     */
    public int start(int i) {
        return start[i];
    }

    /**
     * {@return one past the last component of range {@code i}}
     *
     * @param i range index, in [0, count())
     */
    public int end(int i) {
        return end[i];
    }
}
