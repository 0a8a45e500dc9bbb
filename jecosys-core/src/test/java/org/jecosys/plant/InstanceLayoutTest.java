package org.jecosys.plant;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import org.junit.jupiter.api.Test;

class InstanceLayoutTest {
    @Test
    void recordIsSixteenBytes() {
        assertEquals(16, InstanceLayout.BYTES);
        assertEquals(InstanceLayout.BYTES, InstanceLayout.KIND + 2);
    }

    @Test
    void writesExactlyItsSlotAndRoundTrips() {
        ByteBuffer b = ByteBuffer.allocate(3 * InstanceLayout.BYTES).order(ByteOrder.LITTLE_ENDIAN);
        for (int i = 0; i < b.limit(); i++) {
            b.put(i, (byte) 0x5A);
        }
        InstanceLayout.put(b, 1, 1.5f, 0.25f, -7f, 1.0, 1000, 63);
        for (int i = 0; i < 16; i++) {
            assertEquals((byte) 0x5A, b.get(i));
            assertEquals((byte) 0x5A, b.get(32 + i));
        }
        assertEquals(1.5f, b.getFloat(16 + InstanceLayout.X));
        assertEquals(0.25f, b.getFloat(16 + InstanceLayout.Y));
        assertEquals(-7f, b.getFloat(16 + InstanceLayout.Z));
        int az = b.getShort(16 + InstanceLayout.AZIMUTH) & 0xFFFF;
        assertEquals(1.0, InstanceLayout.unpackAzimuth(az), Math.PI / 65536);
        int kind = b.getShort(16 + InstanceLayout.KIND) & 0xFFFF;
        assertEquals(1000, InstanceLayout.species(kind));
        assertEquals(63, InstanceLayout.variant(kind));
        assertEquals(0, b.position());
    }

    @Test
    void azimuthWraps() {
        assertEquals(InstanceLayout.packAzimuth(0.5), InstanceLayout.packAzimuth(0.5 + 2 * Math.PI));
        assertEquals(InstanceLayout.packAzimuth(-0.5), InstanceLayout.packAzimuth(2 * Math.PI - 0.5));
        assertEquals(0, InstanceLayout.packAzimuth(Math.nextDown(2 * Math.PI)));
    }

    @Test
    void rejectsOutOfRange() {
        assertThrows(IllegalArgumentException.class, () -> InstanceLayout.packKind(1024, 0));
        assertThrows(IllegalArgumentException.class, () -> InstanceLayout.packKind(0, 64));
        ByteBuffer big = ByteBuffer.allocate(16);
        assertThrows(IllegalArgumentException.class, () -> InstanceLayout.put(big, 0, 0, 0, 0, 0, 0, 0));
    }
}
