package org.jecosys.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

class TurnsTest {
    @Test
    void everyConfigurationRunsEveryStepInOrderTakingRotatedTurns() {
        List<String> log = new ArrayList<>();
        Turns.run(3, 5, 2, (c, k) -> log.add(c + ":" + k));
        // rounds of 2 steps (the last of 1), the first turn moving on by one each round
        assertEquals(List.of("0:0", "0:1", "1:0", "1:1", "2:0", "2:1",
                "1:2", "1:3", "2:2", "2:3", "0:2", "0:3",
                "2:4", "0:4", "1:4"), log);
    }

    @Test
    void noStepsRunsNothing() {
        List<String> log = new ArrayList<>();
        Turns.run(2, 0, 4, (c, k) -> log.add(c + ":" + k));
        assertEquals(List.of(), log);
    }
}
