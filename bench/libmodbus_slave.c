/* A fast reference slave for the benchmarks: libmodbus answering as slave 17, holding
 * 400108-400110 = 555, 0, 100.
 *   libmodbus_slave tcp PORT
 *   libmodbus_slave rtu DEVICE
 */
#include <errno.h>
#include <modbus.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

int main(int argc, char **argv) {
    if (argc != 3) {
        fprintf(stderr, "usage: %s tcp PORT | rtu DEVICE\n", argv[0]);
        return 2;
    }
    modbus_mapping_t *map = modbus_mapping_new(10000, 10000, 10000, 10000);
    map->tab_registers[107] = 555;
    map->tab_registers[109] = 100;
    uint8_t query[MODBUS_TCP_MAX_ADU_LENGTH];
    if (strcmp(argv[1], "tcp") == 0) {
        modbus_t *ctx = modbus_new_tcp("127.0.0.1", atoi(argv[2]));
        int server = modbus_tcp_listen(ctx, 1);
        for (;;) {
            int client = modbus_tcp_accept(ctx, &server);
            if (client < 0) return 1;
            int rc;
            while ((rc = modbus_receive(ctx, query)) != -1) {
                if (rc > 0) modbus_reply(ctx, query, rc, map);
            }
            close(client);
        }
    }
    modbus_t *ctx = modbus_new_rtu(argv[2], 19200, 'E', 8, 1);
    modbus_set_slave(ctx, 17);
    if (modbus_connect(ctx) == -1) {
        fprintf(stderr, "%s: %s\n", argv[2], modbus_strerror(errno));
        return 1;
    }
    for (;;) {
        int rc = modbus_receive(ctx, query);
        if (rc > 0) modbus_reply(ctx, query, rc, map);
    }
}
