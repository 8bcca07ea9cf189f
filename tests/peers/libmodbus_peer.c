/* libmodbus as a peer for mbtool's tests of functions 22 (mask write register) and 23
 * (read/write multiple registers), on Modbus TCP at 127.0.0.1.
 *
 *   libmodbus_peer client PORT   mask-writes register 4 (AND 00F2, OR 0025), then writes
 *                                registers 14-16 with 00FF and reads 3-8 in one 23,
 *                                and prints what it read: "mask 0017", "read 1 2 ...".
 *   libmodbus_peer server PORT   serves 100 holding registers, register 4 holding 0012
 *                                and register n holding n for the others, one client at a
 *                                time, until killed.
 */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <modbus.h>

static int client(int port)
{
    modbus_t *ctx = modbus_new_tcp("127.0.0.1", port);
    if (ctx == NULL || modbus_connect(ctx) == -1) {
        fprintf(stderr, "connect: %s\n", modbus_strerror(errno));
        return 1;
    }
    modbus_set_slave(ctx, 17);
    uint16_t value;
    if (modbus_mask_write_register(ctx, 4, 0x00F2, 0x0025) == -1
        || modbus_read_registers(ctx, 4, 1, &value) == -1) {
        fprintf(stderr, "mask write: %s\n", modbus_strerror(errno));
        return 1;
    }
    printf("mask %04X\n", value);
    uint16_t written[3] = {0x00FF, 0x00FF, 0x00FF};
    uint16_t read[6];
    if (modbus_write_and_read_registers(ctx, 14, 3, written, 3, 6, read) == -1) {
        fprintf(stderr, "read/write: %s\n", modbus_strerror(errno));
        return 1;
    }
    printf("read");
    for (int i = 0; i < 6; i++) {
        printf(" %u", read[i]);
    }
    printf("\n");
    modbus_close(ctx);
    modbus_free(ctx);
    return 0;
}

static int server(int port)
{
    modbus_t *ctx = modbus_new_tcp("127.0.0.1", port);
    modbus_mapping_t *mapping = modbus_mapping_new(0, 0, 100, 0);
    if (ctx == NULL || mapping == NULL) {
        return 1;
    }
    for (int i = 0; i < 100; i++) {
        mapping->tab_registers[i] = (uint16_t)i;
    }
    mapping->tab_registers[4] = 0x0012;
    int listener = modbus_tcp_listen(ctx, 1);
    if (listener == -1) {
        fprintf(stderr, "listen: %s\n", modbus_strerror(errno));
        return 1;
    }
    printf("listening\n");
    fflush(stdout);
    for (;;) {
        int socket = modbus_tcp_accept(ctx, &listener);
        if (socket == -1) {
            return 1;
        }
        uint8_t query[MODBUS_TCP_MAX_ADU_LENGTH];
        for (;;) {
            int len = modbus_receive(ctx, query);
            if (len == -1) {
                break;
            }
            if (len > 0) {
                modbus_reply(ctx, query, len, mapping);
            }
        }
        close(socket);
    }
}

int main(int argc, char **argv)
{
    if (argc != 3) {
        fprintf(stderr, "usage: libmodbus_peer client|server PORT\n");
        return 2;
    }
    int port = atoi(argv[2]);
    return strcmp(argv[1], "server") == 0 ? server(port) : client(port);
}
